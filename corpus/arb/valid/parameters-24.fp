!!ARBfp1.0
# twenty-four distinct parameter vectors, the minimum MAX_PROGRAM_PARAMETERS_ARB (ARBfp 3.11.3.6)
# 20 env/local vectors + 4 distinct constants; the repeated constants and the
# repeated binding of program.env[0] count once.
PARAM e[] = { program.env[0..9] };
PARAM l[] = { program.local[0..9] };
PARAM again = program.env[0];
TEMP t;
MUL t, e[0], l[0];
MAD t, e[1], l[1], t;
MAD t, e[2], l[2], t;
MAD t, e[3], l[3], t;
MAD t, e[4], l[4], t;
MAD t, e[5], l[5], t;
MAD t, e[6], l[6], t;
MAD t, e[7], l[7], t;
MAD t, e[8], l[8], t;
MAD t, e[9], l[9], t;
MAD t, t, again, { 1, 2, 3, 4 };
MAD t, t, { 1, 2, 3, 4 }, 0.5;
MAD t, t, 0.5, 0.25;
ADD result.color, t, { 0, 0, 0, 1 };
END
