!!ARBfp1.0
# state.matrix rows of every fragment-visible matrix and modifier (ARBfp 3.11.3.2, Table X.2.7)
PARAM mv0  = state.matrix.modelview.row[0];
PARAM mv1  = state.matrix.modelview[0].row[1];
PARAM pr2  = state.matrix.projection.row[2];
PARAM mvp3 = state.matrix.mvp.row[3];
PARAM tx0  = state.matrix.texture.row[0];
PARAM tx1  = state.matrix.texture[1].row[1];
PARAM pg0  = state.matrix.program[0].row[0];
PARAM pg7  = state.matrix.program[7].row[3];
PARAM inv  = state.matrix.modelview.inverse.row[0];
PARAM tra  = state.matrix.projection.transpose.row[1];
PARAM itr  = state.matrix.modelview.invtrans.row[2];
PARAM ptr  = state.matrix.program[2].invtrans.row[3];
PARAM ttr  = state.matrix.texture[1].transpose.row[0];
TEMP v;
DP4 v.x, mv0, fragment.texcoord[0];
DP4 v.y, mv1, fragment.texcoord[0];
DP4 v.z, pr2, fragment.texcoord[0];
DP4 v.w, mvp3, fragment.texcoord[0];
MAD v, tx0, tx1, v;
MAD v, pg0, pg7, v;
MAD v, inv, tra, v;
MAD v, itr, ptr, v;
ADD v, v, ttr;
DP4 v.x, state.matrix.mvp.row[0], v;
DP4 v.y, state.matrix.program[1].transpose.row[2], v;
MUL result.color, v, fragment.color;
END
