!!ARBfp1.0
# OPTION ARB_precision_hint_fastest (ARBfp 3.11.4.5.2)
OPTION ARB_precision_hint_fastest;
MUL result.color, fragment.color, fragment.color.secondary;
END
