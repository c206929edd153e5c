!!arbfp1.0
# header !!arbfp1.0: the header string is case-sensitive (ARBfp 3.11.2)
# FAIL
# EXPECT-ERROR: 1:1 arb-header-missing
MOV result.color, fragment.color;
END
