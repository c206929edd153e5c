!!ARBfp1.0
# fragment.position counted from the upper left of the window (ARB_fragment_coord_conventions 3.11.4.5.3)
OPTION ARB_fragment_coord_origin_upper_left;
PARAM scale = program.local[0];
MUL result.color, fragment.position, scale;
END
