!!ARBfp1.0
# LRP and LRP_SAT: linear interpolation a*b + (1-a)*c (ARBfp 3.11.5.14)
# Blend two textures by the vertex colour alpha, then towards the texenv colour.
TEMP t0, t1, mix;
TEX t0, fragment.texcoord[0], texture[0], 2D;
TEX t1, fragment.texcoord[1], texture[1], 2D;
LRP mix, fragment.color.a, t0, t1;
LRP_SAT result.color, program.local[1].x, state.texenv[0].color, mix;
END
