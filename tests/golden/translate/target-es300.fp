!!ARBfp1.0
# ARGS: --target es300 --no-comments
# The same program as GLSL ES 3.00 (WebGL 2): state and parameters as uniforms, the
# texture coordinate a named input, the colour a declared output.
PARAM tint = program.local[1];
PARAM fog = state.fog.color;
TEMP t;
TEX t, fragment.texcoord[0], texture[0], 2D;
MAD result.color, t, tint, fog;
END
