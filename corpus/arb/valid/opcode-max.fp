!!ARBfp1.0
# MAX and MAX_SAT: component-wise maximum (ARBfp 3.11.5.16)
# Clamp the lit colour from below by the scene ambient.
TEMP lit;
MUL lit, fragment.color, program.env[2];
MAX lit, lit, state.lightmodel.ambient;
MAX_SAT result.color, lit, 0.0;
END
