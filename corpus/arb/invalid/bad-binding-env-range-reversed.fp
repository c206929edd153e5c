!!ARBfp1.0
# program.env[5..2]: first index after last (ARBfp 3.11.3.2, Table X.2.1)
# FAIL
# EXPECT-ERROR: 5:30 arb-binding-row-range
PARAM e[] = { program.env[5..2] };
MOV result.color, fragment.color;
END
