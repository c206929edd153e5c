!!ARBfp1.0
# NV_fragment_program's pack and unpack instructions: valid, interpreted exactly, but not translatable to GLSL 1.10, which cannot form the bits of a float (NV_fragment_program_option 3.11.5, PK2H/UP2H/PK4UB/UP4UB)
OPTION NV_fragment_program;
TEMP packed, colour;
PK2H packed.x, fragment.texcoord[0];
UP2H colour.xy, packed.x;
PK4UB packed.y, fragment.color;
UP4UB colour.zw, packed.y;
MOV result.color, colour;
END
