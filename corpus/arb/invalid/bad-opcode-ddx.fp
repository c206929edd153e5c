!!ARBfp1.0
# DDX is an instruction of OPTION NV_fragment_program, not of ARB_fragment_program itself (ARBfp 3.11.2 <instruction>; NV_fragment_program_option)
# FAIL
# EXPECT-ERROR: 6:1 arb-option-required
TEMP t;
DDX t, fragment.texcoord[0];
MOV result.color, fragment.color;
END
