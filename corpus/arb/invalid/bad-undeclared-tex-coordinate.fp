!!ARBfp1.0
# an undeclared name as a TEX coordinate (ARBfp 3.11.3)
# FAIL
# EXPECT-ERROR: 5:19 arb-decl-undeclared
TEX result.color, uv, texture[0], 2D;
END
