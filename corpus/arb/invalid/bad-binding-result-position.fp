!!ARBfp1.0
# result.position is a vertex program result (ARBfp 3.11.2 <resultBinding>)
# FAIL
# EXPECT-ERROR: 5:12 arb-binding-stage
MOV result.position, fragment.position;
MOV result.color, fragment.color;
END
