!!ARBfp1.0
# 2049 parameter bindings: beyond what Mesa takes (MAX_PROGRAM_PARAMETERS_ARB 2048) (ARBfp 3.11.3.6)
# FAIL
# EXPECT-ERROR: 6:7 arb-limit-parameters
PARAM l[] = { program.local[0..2047] };
PARAM extra = { 0.5, 0, 0, 1 };
MOV result.color, fragment.color;
END
