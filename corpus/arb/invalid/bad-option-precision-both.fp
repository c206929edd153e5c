!!ARBfp1.0
# both precision hints: fastest then nicest (ARBfp 3.11.4.5.2)
# FAIL
# EXPECT-ERROR: 6:8 arb-option-conflict
OPTION ARB_precision_hint_fastest;
OPTION ARB_precision_hint_nicest;
MOV result.color, fragment.color;
END
