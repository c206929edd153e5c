!!ARBfp1.0
# NV_fragment_program2: REP, LOOP with A0 as the counter, IF/ELSE/ENDIF, BRK, CAL/RET, DIV, DP2A, NRM (NV_fragment_program2)
OPTION NV_fragment_program2;
TEMP sum, n, t;
MOV sum, 0;
REP {4};
  ADD sum, sum, fragment.texcoord[0];
  SGEC t, sum, 2;
  BRK (NE.x);
ENDREP;
NRMH n.xyz, fragment.texcoord[1];
MOVC t, fragment.facing;
IF GT.x;
  CAL light;
ELSE;
  DIV sum, sum, 4;
ENDIF;
DP2A result.color.w, sum, n, fragment.color;
MOV result.color.xyz, sum;
RET;
light:
MUL sum, sum, |n.z|;
RET;
END
