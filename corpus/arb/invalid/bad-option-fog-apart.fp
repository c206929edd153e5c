!!ARBfp1.0
# two fog options separated by a precision hint still conflict (ARBfp 3.11.4.5.1)
# FAIL
# EXPECT-ERROR: 7:8 arb-option-conflict
OPTION ARB_fog_exp2;
OPTION ARB_precision_hint_fastest;
OPTION ARB_fog_linear;
MOV result.color, fragment.color;
END
