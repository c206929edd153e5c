!!ARBfp1.0
# NV_fragment_program: half precision, condition codes, conditional writes, KIL on a test, derivatives (NV_fragment_program_option)
OPTION NV_fragment_program;
SHORT TEMP h;
LONG TEMP l;
TEX l, fragment.texcoord[0], texture[0], 2D;
MULH h, l, fragment.color;
SUBC l, h, 0.5;
KIL LT.w;
MOV result.color, h;
MOV result.color.xyz (GT.xyzw), l;
DDX h, fragment.texcoord[0];
END
