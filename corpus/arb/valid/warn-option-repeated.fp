!!ARBfp1.0
# the same OPTION given twice is redundant (ARBfp 3.11.4.5)
# EXPECT-WARNING: 5:8 arb-option-repeated
OPTION ARB_fog_linear;
OPTION ARB_fog_linear;
MOV result.color, fragment.color;
END
