!!ARBfp1.0
# OUTPUT bound to result.pointsize in a fragment program (ARBfp 3.11.2 <OUTPUT_statement>)
# FAIL
# EXPECT-ERROR: 5:23 arb-binding-stage
OUTPUT psize = result.pointsize;
MOV result.color, fragment.color;
END
