!!ARBfp1.0
# state.texgen is a vertex program binding (ARBfp 3.11.2 <stateSingleItem>)
# FAIL
# EXPECT-ERROR: 5:21 arb-binding-stage
PARAM plane = state.texgen[0].eye.s;
MOV result.color, fragment.color;
END
