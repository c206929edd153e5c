!!ARBfp1.0
# a write mask .abgr: all four components but out of order (ARBfp 3.11.2 <rgbaMask>)
# FAIL
# EXPECT-ERROR: 5:18 arb-operand-mask
MOV result.color.abgr, fragment.color;
END
