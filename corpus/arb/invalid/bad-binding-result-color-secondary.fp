!!ARBfp1.0
# result.color.secondary is a vertex program result (ARBfp 3.11.2 <resultBinding>)
# FAIL
# EXPECT-ERROR: 6:18 arb-binding-stage
MOV result.color, fragment.color;
MOV result.color.secondary, fragment.color.secondary;
END
