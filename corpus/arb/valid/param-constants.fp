!!ARBfp1.0
# constant PARAMs: scalar, 1- to 4-component vectors, signed, inline vectors (ARBfp 3.11.3.2)
PARAM s   = 0.5;                # (0.5, 0.5, 0.5, 0.5)
PARAM ns  = -2.0;               # (-2, -2, -2, -2)
PARAM v1  = { 0.25 };           # (0.25, 0, 0, 1)
PARAM v2  = { 0.25, 0.5 };      # (0.25, 0.5, 0, 1)
PARAM v3  = { 1, -1, 0.5 };     # (1, -1, 0.5, 1)
PARAM v4  = { 0.2125, 0.7154, 0.0721, 0 };
TEMP t;
MAD t, fragment.color, s, v1;
MAD t, t, ns, v2;
MAD t, t, v3, { 0, 0, 0, 1 };
DP3 t.w, t, v4;
MUL result.color, t, { 0.5, 0.5, 0.5, 1.0 };
END
