!!ARBfp1.0
# result.fogcoord is a vertex program result (ARBfp 3.11.2 <resultBinding>)
# FAIL
# EXPECT-ERROR: 5:12 arb-binding-stage
MOV result.fogcoord, fragment.fogcoord;
MOV result.color, fragment.color;
END
