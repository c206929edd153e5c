!!ARBfp1.0
# water: two scrolling normal maps perturb a projective reflection (ARBfp 3.11.6, three indirections)
PARAM scroll = program.env[0];          # (du0, dv0, du1, dv1)
PARAM waveScale = program.local[0];
PARAM waterColor = program.local[1];
TEMP tc0, tc1, n0, n1, n, refl;
ADD tc0, fragment.texcoord[0], scroll;
ADD tc1, fragment.texcoord[0], scroll.zwxy;
TEX n0, tc0, texture[0], 2D;
TEX n1, tc1, texture[0], 2D;
ADD n, n0, n1;
SUB n, n, 1.0;                          # average of the two, expanded to [-1,1]
MOV refl, fragment.texcoord[1];
MAD refl.xy, n, waveScale.x, refl;
TXP refl, refl, texture[1], 2D;
LRP result.color, fragment.color.a, refl, waterColor;
END
