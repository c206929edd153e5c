!!ARBfp1.0
# two fog options: ARB_fog_linear then ARB_fog_exp (ARBfp 3.11.4.5.1)
# FAIL
# EXPECT-ERROR: 6:8 arb-option-conflict
OPTION ARB_fog_linear;
OPTION ARB_fog_exp;
MOV result.color, fragment.color;
END
