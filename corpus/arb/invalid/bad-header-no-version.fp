!!ARBfp
# header !!ARBfp without the version (ARBfp 3.11.2)
# FAIL
# EXPECT-ERROR: 1:1 arb-header-missing
MOV result.color, fragment.color;
END
