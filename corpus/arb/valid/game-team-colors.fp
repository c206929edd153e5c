!!ARBfp1.0
# team colours from an env parameter array weighted by a mask texture (ARBfp 3.11.3.2, 3.11.4.2)
PARAM team[4] = { program.env[8..11] };
TEMP base, mask, c;
TEX base, fragment.texcoord[0], texture[0], 2D;
TEX mask, fragment.texcoord[0], texture[1], 2D;
MUL c, team[0], mask.r;
MAD c, team[1], mask.g, c;
MAD c, team[2], mask.b, c;
MAD c, team[3], mask.a, c;
ADD mask.x, mask.r, mask.g;
ADD mask.x, mask.x, mask.b;
ADD_SAT mask.x, mask.x, mask.a;
LRP result.color.rgb, mask.x, c, base;
MOV result.color.a, base.a;
END
