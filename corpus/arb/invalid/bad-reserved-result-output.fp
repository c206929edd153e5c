!!ARBfp1.0
# result is a reserved word: not an OUTPUT name (ARBfp 3.11.2 <identifier>)
# FAIL
# EXPECT-ERROR: 5:8 arb-syntax-reserved-name
OUTPUT result = result.color;
MOV result.color, fragment.color;
END
