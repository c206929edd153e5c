!!ARBfp1.0
# an ALIAS of a name declared only later (ARBfp 3.11.3.5: an established name)
# FAIL
# EXPECT-ERROR: 5:15 arb-decl-alias-undeclared
ALIAS shade = work;
TEMP work;
MOV result.color, fragment.color;
END
