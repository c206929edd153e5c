!!ARBfp1.0
# NV_fragment_program_option's packing (PK2H, PK2US, PK4B, PK4UB) and unpacking (UP2H, UP2US,
# UP4B, UP4UB): each packed value unpacked again, and the packed bits themselves
OPTION NV_fragment_program;
OPTION ARB_draw_buffers;
TEMP p, h, us, b, ub;
PK2H p.x, fragment.texcoord[0];
PK2US p.y, fragment.color;
PK4B p.z, fragment.texcoord[1];
PK4UB p.w, fragment.color;
UP2H h, p.x;
UP2US us, p.y;
UP4B b, p.z;
UP4UB ub, p.w;
MOV result.color[0], h;
MOV result.color[1], us;
MOV result.color[2], b;
MOV result.color[3], ub;
END
