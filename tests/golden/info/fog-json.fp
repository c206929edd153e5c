!!ARBfp1.0
# ARGS: --format json
OPTION ARB_fog_linear;
PARAM c[2] = { program.env[0..1] };
TEMP t;
TEX t, fragment.texcoord[0], texture[1], 2D;
MAD t, t, c[0], state.fog.color;
MUL result.color, t, program.local[3];
END
