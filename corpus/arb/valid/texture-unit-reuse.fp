!!ARBfp1.0
# one unit sampled many times with the same target by TEX, TXP and TXB (ARBfp 3.11.6)
# Three-tap blur along s on unit 0.
TEMP tc, sum, s;
TEX sum, fragment.texcoord[0], texture[0], 2D;
ADD tc, fragment.texcoord[0], { 0.01, 0, 0, 1 };
TXP s, tc, texture[0], 2D;
ADD sum, sum, s;
SUB tc, fragment.texcoord[0], { 0.01, 0, 0, 0 };
TXB s, tc, texture[0], 2D;
ADD sum, sum, s;
MUL result.color, sum, 0.33333;
END
