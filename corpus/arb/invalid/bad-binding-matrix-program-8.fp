!!ARBfp1.0
# state.matrix.program[8]: beyond MAX_PROGRAM_MATRICES_ARB (8) (ARBfp 3.11.2 <stateProgramMatNum>)
# FAIL
# EXPECT-ERROR: 5:32 arb-binding-index-range
PARAM r = state.matrix.program[8].row[0];
MOV result.color, fragment.color;
END
