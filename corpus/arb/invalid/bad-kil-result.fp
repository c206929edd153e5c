!!ARBfp1.0
# KIL of result.color: results are write-only (ARBfp 3.11.3.4)
# FAIL
# EXPECT-ERROR: 6:5 arb-operand-src-writeonly
MOV result.color, fragment.color;
KIL result.color;
END
