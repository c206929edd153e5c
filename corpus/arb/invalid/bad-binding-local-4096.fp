!!ARBfp1.0
# program.local[4096]: beyond MAX_PROGRAM_LOCAL_PARAMETERS_ARB (4096 on Mesa) (ARBfp 3.11.2 <progLocalParamNum>)
# FAIL
# EXPECT-ERROR: 5:25 arb-binding-index-range
PARAM l = program.local[4096];
MOV result.color, fragment.color;
END
