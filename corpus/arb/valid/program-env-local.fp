!!ARBfp1.0
# program.env[n] and program.local[n], declared and inline, at the minimum range ends (ARBfp 3.11.3.2, Table X.2.1)
PARAM e0  = program.env[0];
PARAM e23 = program.env[23];
PARAM l0  = program.local[0];
PARAM l23 = program.local[23];
TEMP c;
MAD c, fragment.color, e0, l0;
MAD c, c, e23, l23;
MAD c, c, program.env[12], program.local[12];
MOV result.color, c;
END
