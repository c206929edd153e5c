!!ARBfp1.0
# ARGS: --target es100
# GLSL ES 1.00 has no 3D textures: refused, naming the construct and the target.
TEMP t;
TEX t, fragment.texcoord[0], texture[0], 3D;
MOV result.color, t;
END
