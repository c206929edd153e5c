!!ARBfp1.0
# ARGS: -Werror
# a warning (SCS leaves z and w undefined) becomes an error
TEMP t;
SCS t, fragment.texcoord[0].x;
MOV result.color, t;
END
