!!ARBfp1.0
# fragment is a reserved word: not a TEMP name (ARBfp 3.11.2 <identifier>)
# FAIL
# EXPECT-ERROR: 5:12 arb-syntax-reserved-name
TEMP base, fragment;
MOV result.color, fragment.color;
END
