!!ARBfp1.0
# every fragment attribute binding used inline in instructions (ARBfp 3.11.3.1)
TEMP t, u;
MUL t, fragment.color, fragment.color.primary;
ADD t, t, fragment.color.secondary;
TEX u, fragment.texcoord, texture[0], 2D;
MUL t, t, u;
TEX u, fragment.texcoord[1], texture[1], 2D;
MAD t, u, fragment.texcoord[0], t;
MUL t.a, t.a, fragment.fogcoord.x;
MAD result.color, fragment.position.w, 0.001, t;
END
