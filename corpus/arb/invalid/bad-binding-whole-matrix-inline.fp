!!ARBfp1.0
# a whole matrix used inline as an operand (ARBfp 3.11.2 <paramSingleItemUse>)
# FAIL
# EXPECT-ERROR: 6:10 arb-binding-matrix-rows
TEMP t;
DP4 t.x, state.matrix.texture[0], fragment.texcoord[0];
MOV result.color, fragment.color;
END
