!!ARBfp1.0
# twenty-five texture instructions: beyond the minimum MAX_PROGRAM_TEX_INSTRUCTIONS_ARB of 24 (ARBfp 3.11.3.6)
# no warning by default (Mesa takes it); --limits spec-min rejects it
TEMP s, acc;
TEX s, fragment.texcoord[0], texture[0], 2D;
TEX s, fragment.texcoord[1], texture[1], 2D;
TEX s, fragment.texcoord[0], texture[0], 2D;
TEX s, fragment.texcoord[1], texture[1], 2D;
TEX s, fragment.texcoord[0], texture[0], 2D;
TEX s, fragment.texcoord[1], texture[1], 2D;
TEX s, fragment.texcoord[0], texture[0], 2D;
TEX s, fragment.texcoord[1], texture[1], 2D;
TEX s, fragment.texcoord[0], texture[0], 2D;
TEX s, fragment.texcoord[1], texture[1], 2D;
TEX s, fragment.texcoord[0], texture[0], 2D;
TEX s, fragment.texcoord[1], texture[1], 2D;
TEX s, fragment.texcoord[0], texture[0], 2D;
TEX s, fragment.texcoord[1], texture[1], 2D;
TEX s, fragment.texcoord[0], texture[0], 2D;
TEX s, fragment.texcoord[1], texture[1], 2D;
TEX s, fragment.texcoord[0], texture[0], 2D;
TEX s, fragment.texcoord[1], texture[1], 2D;
TEX s, fragment.texcoord[0], texture[0], 2D;
TEX s, fragment.texcoord[1], texture[1], 2D;
TEX s, fragment.texcoord[0], texture[0], 2D;
TEX s, fragment.texcoord[1], texture[1], 2D;
TEX s, fragment.texcoord[0], texture[0], 2D;
TEX s, fragment.texcoord[1], texture[1], 2D;
TEX acc, fragment.texcoord[0], texture[0], 2D;
ADD result.color, acc, s;
END
