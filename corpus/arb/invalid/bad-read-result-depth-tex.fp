!!ARBfp1.0
# result.depth as a texture coordinate (ARBfp 3.11.3.4)
# FAIL
# EXPECT-ERROR: 6:19 arb-operand-src-writeonly
MOV result.depth.z, fragment.position.z;
TEX result.color, result.depth, texture[0], 2D;
END
