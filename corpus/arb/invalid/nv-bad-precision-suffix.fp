!!ARBfp1.0
# DST has no X precision form: table X.5 of NV_fragment_program_option lists R and H only (NV_fragment_program_option 3.11.4)
# FAIL
# EXPECT-ERROR: 7:1 arb-syntax-modifier
OPTION NV_fragment_program;
TEMP d;
DSTX d, fragment.color, fragment.texcoord[0];
MOV result.color, d;
END
