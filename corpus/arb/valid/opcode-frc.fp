!!ARBfp1.0
# FRC and FRC_SAT: component-wise fraction (ARBfp 3.11.5.11)
# Tile a texture N times (tiling factors in local 0) with explicit wrap.
PARAM tiles = program.local[0];
TEMP tc;
MUL tc, fragment.texcoord[0], tiles;
FRC tc, tc;
FRC_SAT tc.zw, fragment.texcoord[0];
TEX result.color, tc, texture[0], 2D;
END
