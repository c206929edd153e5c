!!ARBfp1.0
# ARGS: --engines ref,mesa-glsl330,mesa-es300,mesa-es100 --vectors 8
# A RECT lookup: the glsl330 engine runs it, GLSL ES has no RECT samplers (not applicable).
TEX result.color, fragment.texcoord[0], texture[0], RECT;
END
