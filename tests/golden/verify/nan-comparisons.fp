!!ARBfp1.0
# ARGS: --vectors 8
# The edge vectors' NaN and infinities through SGE and a product: 0 times an infinity or NaN
# is undefined (ARBfp 3.11.5.19 rule 2: NaN and infinity "may be exceptions" to 0 * x = 0),
# and mesa-glsl's folded comparison of a NaN is the known deviation nan-compare-folded.
TEMP R0, R1;
SGE R0, fragment.color, fragment.color.yzxw;
SGE R1, fragment.color, fragment.color.zxyw;
MUL R0, R0, R1;
MUL result.color, R0, fragment.color;
END
