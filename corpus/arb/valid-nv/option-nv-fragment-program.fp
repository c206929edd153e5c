!!ARBfp1.0
# OPTION NV_fragment_program: the NV instruction set in an ARB fragment program; a program using none of it is a plain ARB program (NV_fragment_program_option)
OPTION NV_fragment_program;
MOV result.color, fragment.color;
END
