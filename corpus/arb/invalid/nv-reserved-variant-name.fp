!!ARBfp1.0
# NV_fragment_program_option reserves every instruction name and variant of its table X.5:
# MULH_SAT (MUL at half precision, saturated) cannot name a temporary.
# FAIL
# EXPECT-ERROR: 7:6 arb-syntax-reserved-name
OPTION NV_fragment_program;
TEMP MULH_SAT;
MOV result.color, fragment.color;
END
