!!ARBfp1.0
# a TEMP used before its declaration (ARBfp 3.11.3: previously declared)
# FAIL
# EXPECT-ERROR: 5:5 arb-decl-undeclared
MOV work, fragment.color;
TEMP work;
MOV work, fragment.color;
MOV result.color, work;
END
