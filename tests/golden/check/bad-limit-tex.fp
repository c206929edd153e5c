!!ARBfp1.0
# ARGS: --limits spec-min
# 25 texture instructions: one more than the minimum of 24
TEMP r;
TEX r, fragment.texcoord, texture, 2D;
TEX r, fragment.texcoord, texture, 2D;
TEX r, fragment.texcoord, texture, 2D;
TEX r, fragment.texcoord, texture, 2D;
TEX r, fragment.texcoord, texture, 2D;
TEX r, fragment.texcoord, texture, 2D;
TEX r, fragment.texcoord, texture, 2D;
TEX r, fragment.texcoord, texture, 2D;
TEX r, fragment.texcoord, texture, 2D;
TEX r, fragment.texcoord, texture, 2D;
TEX r, fragment.texcoord, texture, 2D;
TEX r, fragment.texcoord, texture, 2D;
TEX r, fragment.texcoord, texture, 2D;
TEX r, fragment.texcoord, texture, 2D;
TEX r, fragment.texcoord, texture, 2D;
TEX r, fragment.texcoord, texture, 2D;
TEX r, fragment.texcoord, texture, 2D;
TEX r, fragment.texcoord, texture, 2D;
TEX r, fragment.texcoord, texture, 2D;
TEX r, fragment.texcoord, texture, 2D;
TEX r, fragment.texcoord, texture, 2D;
TEX r, fragment.texcoord, texture, 2D;
TEX r, fragment.texcoord, texture, 2D;
TEX r, fragment.texcoord, texture, 2D;
TEX r, fragment.texcoord, texture, 2D;
MOV result.color, r;
END
