!!ARBfp1.0
# ARGS: --vectors 8
# Every engine agrees: the summary line per program and for the run.
TEMP t;
MUL t, fragment.color, fragment.texcoord[0];
LRP result.color, fragment.texcoord[1].x, t, fragment.color.secondary;
END
