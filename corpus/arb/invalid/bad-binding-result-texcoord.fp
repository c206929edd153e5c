!!ARBfp1.0
# result.texcoord is a vertex program result (ARBfp 3.11.2 <resultBinding>)
# FAIL
# EXPECT-ERROR: 6:12 arb-binding-stage
MOV result.color, fragment.color;
MOV result.texcoord[0], fragment.texcoord[0];
END
