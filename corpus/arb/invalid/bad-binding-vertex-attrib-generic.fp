!!ARBfp1.0
# vertex.attrib[n] in a fragment program (ARBfp 3.11.2 <fragAttribBinding>)
# FAIL
# EXPECT-ERROR: 5:35 arb-binding-stage
MUL result.color, fragment.color, vertex.attrib[1];
END
