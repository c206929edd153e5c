!!ARBfp1.0
# every floatConstant form: integer, point, fraction, exponent with and without sign (ARBfp 3.11.2)
PARAM ints  = { 0, 1, 2, 10 };
PARAM fracs = { 1.5, 2., .25, 0.0 };
PARAM exps  = { 1e2, 1E2, 2.5e-1, .5e+1 };
PARAM mixed = { 5.e-1, 1.0E+0, 0.000001, 3.4e38 };
PARAM sgn   = { -1, +2.0, -.5, -1e-3 };
TEMP t;
MAD t, ints, fracs, exps;
MAD t, t, mixed, sgn;
MUL t, t, 0.015625;
MAD t, t, 1e-2, 7.;
ADD result.color, t, .125;
END
