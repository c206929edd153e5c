!!ARBfp1.0
# result.depth written from its z component (ARBfp 3.11.3.4, Table X.3)
# Depth sprite: push each texel back by its height map value.
TEMP base, d;
TEX base, fragment.texcoord[0], texture[0], 2D;
MAD d.z, base.a, program.local[0].x, fragment.position.z;
MOV result.depth.z, d.z;
MOV result.color, base;
END
