!!ARBfp1.1
# header !!ARBfp1.1 is not a program header (ARBfp 3.11.2)
# FAIL
# EXPECT-ERROR: 1:1 arb-header-missing
MOV result.color, fragment.color;
END
