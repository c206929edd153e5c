!!ARBfp1.0
# NV_fragment_program2: IF, LOOP and REP as GLSL blocks, BRK, and the new ALU instructions.
OPTION NV_fragment_program2;
PARAM loop = { 4, 0, 1, 0 };
TEMP t, u;
MOV t, 0;
MOVC u, fragment.color;
IF GT.x;
  LOOP loop;
    ADD t, t, fragment.texcoord[1];
    SUBC u.w, u, 0.25;
    BRK (LE.w);
  ENDLOOP;
ELSE;
  REP loop.x;
    ADD t, t, 0.5;
  ENDREP;
ENDIF;
NRM u, t;
DIV u.xy, u, t.w;
DP2A u.w, u, t, t.z;
TXL t, u, texture[0], 2D;
MUL_SSAT result.color, t, fragment.facing.x;
END
