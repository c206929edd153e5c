!!ARBfp1.0
# program.env[256]: beyond MAX_PROGRAM_ENV_PARAMETERS_ARB (256 on Mesa) (ARBfp 3.11.2 <progEnvParamNum>)
# FAIL
# EXPECT-ERROR: 5:47 arb-binding-index-range
MUL result.color, fragment.color, program.env[256];
END
