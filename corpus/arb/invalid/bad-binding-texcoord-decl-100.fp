!!ARBfp1.0
# ATTRIB bound to fragment.texcoord[100] (ARBfp 3.11.2 <texCoordNum>)
# FAIL
# EXPECT-ERROR: 5:31 arb-binding-index-range
ATTRIB tc = fragment.texcoord[100];
MOV result.color, fragment.color;
END
