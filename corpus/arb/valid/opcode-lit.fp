!!ARBfp1.0
# LIT and LIT_SAT: lighting coefficients (ARBfp 3.11.5.13)
# Blinn-Phong from a normal map; light vector in texcoord 1, half vector from state.
PARAM shininess = state.material.shininess;
TEMP nrm, coef, spec;
TEX nrm, fragment.texcoord[0], texture[0], 2D;
MAD nrm, nrm, 2.0, -1.0;
DP3 coef.x, nrm, fragment.texcoord[1];        # N.L
DP3 coef.y, nrm, state.light[0].half;         # N.H
MOV coef.z, 0.0;
MOV coef.w, shininess.x;
LIT coef, coef;
MAD spec, coef.z, state.lightprod[0].specular, state.lightprod[0].ambient;
MAD result.color, coef.y, state.lightprod[0].diffuse, spec;
LIT_SAT coef, coef;
END
