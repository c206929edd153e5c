!!ARBfp1.0
# fragment.texcoord[] with no number (ARBfp 3.11.2 <optTexCoordNum>)
# FAIL
# EXPECT-ERROR: 5:37 arb-syntax-expected
MOV result.color, fragment.texcoord[];
END
