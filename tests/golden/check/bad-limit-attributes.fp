!!ARBfp1.0
# ARGS: --limits spec-min
# 11 attributes: one more than the minimum of 10 (fragment.texcoord[2] and up are
# also beyond the minimum of two texture coordinate sets)
TEMP t;
ADD t, fragment.color, fragment.color.secondary;
ADD t, t, fragment.fogcoord;
ADD t, t, fragment.position;
ADD t, t, fragment.texcoord[0];
ADD t, t, fragment.texcoord[1];
ADD t, t, fragment.texcoord[2];
ADD t, t, fragment.texcoord[3];
ADD t, t, fragment.texcoord[4];
ADD t, t, fragment.texcoord[5];
ADD t, t, fragment.texcoord[6];
MOV result.color, t;
END
