!!ARBfp1.0
# program.local[20..31] range ending beyond the minimum of 24 local parameters (ARBfp 3.11.3.2)
# no warning by default (Mesa takes it); --limits spec-min rejects it
PARAM coeffs[] = { program.local[20..31] };
TEMP c;
MUL c, fragment.color, coeffs[0];
MAD result.color, c, coeffs[11], coeffs[5];
END
