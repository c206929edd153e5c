!!ARBfp1.0
# fragment.position at whole-pixel centres: FRC of x and y is 0 (ARB_fragment_coord_conventions 3.11.4.5.3)
OPTION ARB_fragment_coord_pixel_center_integer;
OPTION ARB_fragment_coord_origin_upper_left;
MOV result.color, {0.0, 0.0, 0.0, 0.0};
FRC result.color.xy, fragment.position;
END
