!!ARBfp1.0
# program is a reserved word: not an ATTRIB name (ARBfp 3.11.2 <identifier>)
# FAIL
# EXPECT-ERROR: 5:8 arb-syntax-reserved-name
ATTRIB program = fragment.color;
MOV result.color, fragment.color;
END
