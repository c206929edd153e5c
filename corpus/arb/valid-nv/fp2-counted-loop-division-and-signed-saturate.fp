!!ARBfp1.0
# NV_fragment_program2: REP with a constant count left early by BRK, DIV by one component, RFL and _SSAT, each in its own channel (NV_fragment_program2, NV_fragment_program_option)
OPTION NV_fragment_program2;
TEMP sum, t, d, r, s;
MOV sum, 0;
REP {3};
  ADD sum, sum, fragment.texcoord[0];
  SGEC t.x, sum.x, 1;
  BRK (NE.x);
ENDREP;
DIV d, fragment.texcoord[1], fragment.texcoord[2].y;
RFL r.xyz, fragment.texcoord[1], fragment.texcoord[2];
ADD_SSAT s, fragment.texcoord[1], -fragment.texcoord[2];
MOV result.color.x, sum.x;
MOV result.color.y, d.x;
MOV result.color.z, r.z;
MOV result.color.w, s.w;
END
