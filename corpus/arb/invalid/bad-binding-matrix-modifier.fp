!!ARBfp1.0
# state.matrix.mvp.inversetranspose: the modifier is invtrans (ARBfp 3.11.2 <stateMatModifier>)
# FAIL
# EXPECT-ERROR: 5:29 arb-binding-unknown
PARAM r0 = state.matrix.mvp.inversetranspose.row[0];
MOV result.color, fragment.color;
END
