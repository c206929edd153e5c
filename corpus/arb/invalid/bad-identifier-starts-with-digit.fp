!!ARBfp1.0
# an identifier may not start with a digit (ARBfp 3.11.2 <identifier>)
# FAIL
# EXPECT-ERROR: 5:6 arb-syntax-expected
TEMP 2base;
MOV result.color, fragment.color;
END
