!!ARBfp1.0
# CMP on interpolated values: a < 0 selects the second operand; 0 and -0 select the third
# (ARBfp 3.11.5.3).
CMP result.color, fragment.texcoord[0], fragment.color, fragment.texcoord[1];
END
