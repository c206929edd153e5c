!!ARBfp1.0
# NV_fragment_program: an fp32 result stored in a SHORT (fp16) register, which holds infinity past 65504, and the X precision suffix (fx12, s1.10 fixed point) on operands and result (NV_fragment_program_option 3.11.4.2)
OPTION NV_fragment_program;
SHORT TEMP h;
LONG TEMP x;
MULR h, fragment.texcoord[0], fragment.texcoord[1];
MULX x, fragment.texcoord[0], fragment.texcoord[1];
MOV result.color.xy, h;
MOV result.color.zw, x;
END
