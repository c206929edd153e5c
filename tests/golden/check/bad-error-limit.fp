!!ARBfp1.0
# ARGS: --error-limit 2
MOV result.color, x;
MOV result.color, y;
MOV result.color, z;
END
