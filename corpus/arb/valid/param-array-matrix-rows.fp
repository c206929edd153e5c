!!ARBfp1.0
# PARAM arrays of whole matrices, row ranges and mixed items (ARBfp 3.11.3.2 <stateMatrixRows>)
PARAM mvp[4] = { state.matrix.mvp };
PARAM texRows[] = { state.matrix.texture[1].row[0..1] };
PARAM prog[] = { state.matrix.program[0].transpose.row[1..3] };
PARAM mixed[7] = { { 1, 0, 0, 0 }, state.fog.color, program.env[3],
                   state.matrix.projection.row[2..2], program.local[4..5], -0.5 };
TEMP v, w;
DP4 v.x, mvp[0], fragment.texcoord[0];
DP4 v.y, mvp[1], fragment.texcoord[0];
DP4 v.z, mvp[2], fragment.texcoord[0];
DP4 v.w, mvp[3], fragment.texcoord[0];
DP4 w.x, texRows[0], v;
DP4 w.y, texRows[1], v;
DP4 w.z, prog[0], v;
DP4 w.w, prog[2], v;
MAD w, w, prog[1], mixed[0];
MAD w, w, mixed[1], mixed[2];
MAD w, w, mixed[3], mixed[4];
MAD w, w, mixed[5], mixed[6];
MUL result.color, w, fragment.color;
END
