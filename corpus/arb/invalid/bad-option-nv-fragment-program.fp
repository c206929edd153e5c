!!ARBfp1.0
# OPTION NV_fragment_program: not supported by the implementation (ARBfp 3.11.4.5)
# FAIL
# EXPECT-ERROR: 5:8 arb-option-unknown
OPTION NV_fragment_program;
MOV result.color, fragment.color;
END
