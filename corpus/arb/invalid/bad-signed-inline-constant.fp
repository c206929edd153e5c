!!ARBfp1.0
# a second sign inside an inline scalar constant: --2.0 (ARBfp 3.11.2 <paramConstScalarUse>)
# FAIL
# EXPECT-ERROR: 5:36 arb-operand-signed-constant
MUL result.color, fragment.color, --2.0;
END
