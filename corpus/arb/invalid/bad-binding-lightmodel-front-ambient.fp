!!ARBfp1.0
# state.lightmodel.front takes only scenecolor, not ambient (ARBfp 3.11.2 <stateLModProperty>)
# FAIL
# EXPECT-ERROR: 5:58 arb-binding-unknown
MUL result.color, fragment.color, state.lightmodel.front.ambient;
END
