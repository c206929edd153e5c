!!ARBfp1.0
# an OPTION after an instruction (ARBfp 3.11.4.5: options come first)
# FAIL
# EXPECT-ERROR: 6:1 arb-syntax-option-placement
MOV result.color, fragment.color;
OPTION ARB_precision_hint_fastest;
END
