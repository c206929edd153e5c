!!ARBfp1.0
# an OPTION after a TEMP declaration (ARBfp 3.11.2 <program>: options precede statements)
# FAIL
# EXPECT-ERROR: 7:1 arb-syntax-option-placement
OPTION ARB_fog_exp;
TEMP c;
OPTION ARB_precision_hint_nicest;
MOV c, fragment.color;
MOV result.color, c;
END
