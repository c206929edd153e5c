!!ARBfp1.0
# a misspelled option name (ARBfp 3.11.4.5: unsupported options fail)
# FAIL
# EXPECT-ERROR: 5:8 arb-option-unknown
OPTION ARB_fog_linaer;
MOV result.color, fragment.color;
END
