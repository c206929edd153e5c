!!ARBfp1.0
# ATTRIB bound to vertex.normal in a fragment program (ARBfp 3.11.2 <ATTRIB_statement>)
# FAIL
# EXPECT-ERROR: 5:14 arb-binding-stage
ATTRIB nrm = vertex.normal;
MOV result.color, fragment.color;
END
