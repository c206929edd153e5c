!!ARBfp1.0
# state.matrix.texture[2]: beyond the minimum of 2 texture coordinate sets (ARBfp 3.11.3.2, Table X.2.7)
# no warning by default (Mesa takes it); --limits spec-min rejects it
TEMP tc;
DP4 tc.x, state.matrix.texture[2].row[0], fragment.texcoord[0];
MOV tc.yzw, fragment.texcoord[0];
TEX result.color, tc, texture[0], 2D;
END
