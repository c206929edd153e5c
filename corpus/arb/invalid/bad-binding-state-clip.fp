!!ARBfp1.0
# state.clip[n].plane is a vertex program binding (ARBfp 3.11.2 <stateSingleItem>)
# FAIL
# EXPECT-ERROR: 5:21 arb-binding-stage
PARAM plane = state.clip[0].plane;
MOV result.color, fragment.color;
END
