!!ARBfp1.0
# ARGS: --format sarif
TEMP t;
MOV t.xg, fragment.color;
MOV result.color, t
END
