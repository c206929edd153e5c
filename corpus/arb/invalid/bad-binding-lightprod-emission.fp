!!ARBfp1.0
# state.lightprod[n] has no emission product (ARBfp 3.11.2 <stateLProdProperty>)
# FAIL
# EXPECT-ERROR: 5:54 arb-binding-unknown
MUL result.color, fragment.color, state.lightprod[0].emission;
END
