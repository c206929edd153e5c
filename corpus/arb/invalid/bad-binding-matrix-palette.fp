!!ARBfp1.0
# state.matrix.palette needs ARB_matrix_palette, which Mesa lacks (ARBfp 3.11.2 <statePaletteMatNum>)
# FAIL
# EXPECT-ERROR: 5:24 arb-binding-unsupported
PARAM r = state.matrix.palette[0].row[0];
MOV result.color, fragment.color;
END
