!!ARBfp1.0
# signed detail texture faded out with distance (ARBfp 3.11.5.15)
PARAM fade = program.local[0];          # x = 1 / fade distance
TEMP base, detail, f;
TEX base, fragment.texcoord[0], texture[0], 2D;
TEX detail, fragment.texcoord[1], texture[1], 2D;
MAD detail, detail, 2.0, -1.0;
MUL_SAT f.x, fragment.fogcoord.x, fade.x;
SUB f.x, 1.0, f.x;
MUL detail, detail, f.x;
MAD result.color, detail, base, base;
END
