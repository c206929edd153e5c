!!ARBfp1.0
# a read of result.color (ARBfp 3.11.3.4: results are write-only)
# FAIL
# EXPECT-ERROR: 6:19 arb-operand-src-writeonly
MOV result.color, fragment.color;
ADD result.color, result.color, fragment.color.secondary;
END
