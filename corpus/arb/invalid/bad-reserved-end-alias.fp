!!ARBfp1.0
# END is a reserved word: not an ALIAS name (ARBfp 3.11.2 <identifier>)
# FAIL
# EXPECT-ERROR: 6:7 arb-syntax-reserved-name
TEMP t;
ALIAS END = t;
MOV result.color, fragment.color;
END
