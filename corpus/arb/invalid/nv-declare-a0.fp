!!ARBfp1.0
# NV_fragment_program2 predefines the address register A0 (the loop index); a program cannot
# declare a variable of that name.
# FAIL
# EXPECT-ERROR: 7:6 arb-syntax-reserved-name
OPTION NV_fragment_program2;
TEMP A0;
MOV result.color, fragment.color;
END
