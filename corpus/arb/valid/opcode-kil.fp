!!ARBfp1.0
# KIL: kill the fragment when a component is negative (ARBfp 3.11.6.4)
# Alpha test done in the program: reject texels below the reference alpha.
PARAM alphaRef = program.local[0];
TEMP base, test;
TEX base, fragment.texcoord[0], texture[0], 2D;
SUB test, base.a, alphaRef.x;
KIL test;
MUL result.color, base, fragment.color;
END
