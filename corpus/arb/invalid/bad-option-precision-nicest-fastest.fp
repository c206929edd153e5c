!!ARBfp1.0
# both precision hints: nicest then fastest (ARBfp 3.11.4.5.2)
# FAIL
# EXPECT-ERROR: 6:8 arb-option-conflict
OPTION ARB_precision_hint_nicest;
OPTION ARB_precision_hint_fastest;
MOV result.color, fragment.color;
END
