!!ARBfp1.0
# option names are case-sensitive: arb_fog_exp is unknown (ARBfp 3.11.4.5)
# FAIL
# EXPECT-ERROR: 5:8 arb-option-unknown
OPTION arb_fog_exp;
MOV result.color, fragment.color;
END
