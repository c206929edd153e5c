!!ARBfp1.0
# OPTION without an identifier (ARBfp 3.11.2 <option>)
# FAIL
# EXPECT-ERROR: 5:8 arb-syntax-expected
OPTION ;
MOV result.color, fragment.color;
END
