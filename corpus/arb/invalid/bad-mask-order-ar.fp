!!ARBfp1.0
# a write mask out of rgba order: .ar (ARBfp 3.11.2 <rgbaMask>)
# FAIL
# EXPECT-ERROR: 6:18 arb-operand-mask
MOV result.color, fragment.color;
MOV result.color.ar, fragment.color.secondary;
END
