!!ARBfp1.0
# DDX (NV_fragment_program_option) is not an ARB instruction (ARBfp 3.11.2 <instruction>)
# FAIL
# EXPECT-ERROR: 6:1 arb-syntax-unknown-instruction
TEMP t;
DDX t, fragment.texcoord[0];
MOV result.color, fragment.color;
END
