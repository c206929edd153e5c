!!ARBfp1.0
# MOV and MOV_SAT: copy a vector (ARBfp 3.11.5.18)
# Pass-through of the interpolated colour with an explicit temporary.
TEMP c;
MOV c, fragment.color;
MOV c.a, 1.0;
MOV_SAT result.color, c;
END
