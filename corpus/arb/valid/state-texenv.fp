!!ARBfp1.0
# state.texenv.color and state.texenv[n].color (ARBfp 3.11.3.2, Table X.2.4)
# GL_BLEND-style combiner reproduced with the texture environment colours.
PARAM env   = state.texenv.color;
PARAM env0  = state.texenv[0].color;
PARAM env1  = state.texenv[1].color;
TEMP t0, t1;
TEX t0, fragment.texcoord[0], texture[0], 2D;
LRP t0.rgb, t0, env, fragment.color;
MUL t0.a, t0.a, env0.a;
TEX t1, fragment.texcoord[1], texture[1], 2D;
LRP result.color.rgb, t1, env1, t0;
MUL result.color.a, t0.a, t1.a;
END
