!!ARBfp1.0
# ATTRIB declarations of every fragment attribute binding (ARBfp 3.11.3.1, Table X.1)
ATTRIB col    = fragment.color;
ATTRIB colPri = fragment.color.primary;
ATTRIB colSec = fragment.color.secondary;
ATTRIB tc     = fragment.texcoord;
ATTRIB tc0    = fragment.texcoord[0];
ATTRIB tc1    = fragment.texcoord[1];
ATTRIB fogc   = fragment.fogcoord;
ATTRIB wpos   = fragment.position;
TEMP t, u;
MUL t, col, colPri;
ADD t, t, colSec;
TEX u, tc, texture[0], 2D;
MUL t, t, u;
TEX u, tc0, texture[0], 2D;
MAD t, u, tc1, t;
MUL t.a, t.a, fogc.x;
MAD result.color, wpos.w, 0.001, t;
END
