!!ARBfp1.0
# index 4 into a PARAM array of a whole matrix (ARBfp 3.11.3.2)
# FAIL
# EXPECT-ERROR: 10:14 arb-operand-index-range
PARAM mvp[] = { state.matrix.mvp };
TEMP p;
DP4 p.x, mvp[0], fragment.texcoord[0];
DP4 p.y, mvp[1], fragment.texcoord[0];
DP4 p.z, mvp[2], fragment.texcoord[0];
DP4 p.w, mvp[4], fragment.texcoord[0];
MOV result.color, p.xyzz;
END
