!!ARBfp1.0
# tokens after END: the program ends with END (ARBfp 3.11.2 <program>)
# FAIL
# EXPECT-ERROR: 7:1 arb-syntax-after-end
MOV result.color, fragment.color;
END
MOV result.color, fragment.texcoord[0];
