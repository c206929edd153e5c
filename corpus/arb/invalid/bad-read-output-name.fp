!!ARBfp1.0
# a read of an OUTPUT name (ARBfp 3.11.3.4)
# FAIL
# EXPECT-ERROR: 8:8 arb-operand-src-writeonly
OUTPUT oc = result.color;
TEMP t;
MOV oc, fragment.color;
MUL t, oc, 0.5;
END
