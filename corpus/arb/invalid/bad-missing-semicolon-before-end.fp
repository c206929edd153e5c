!!ARBfp1.0
# the last instruction before END lacks its ; (ARBfp 3.11.2 <statement>)
# FAIL
# EXPECT-ERROR: 5:33 arb-syntax-missing-semicolon
MOV result.color, fragment.color
END
