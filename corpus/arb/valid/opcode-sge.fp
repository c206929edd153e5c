!!ARBfp1.0
# SGE and SGE_SAT: set on greater or equal (ARBfp 3.11.5.24)
# Two-tone cel step: 1 where the diffuse term reaches the threshold.
TEMP ndotl, step;
DP3 ndotl, fragment.texcoord[0], fragment.texcoord[1];
SGE step, ndotl, program.local[0].x;
SGE_SAT step.w, 1.0, 0.0;
LRP result.color, step, fragment.color, state.lightmodel.ambient;
END
