!!ARBfp1.0
# ATTRIB fragment.color.tertiary: the colour type is primary or secondary (ARBfp 3.11.2 <optColorType>)
# FAIL
# EXPECT-ERROR: 5:29 arb-binding-unknown
ATTRIB col = fragment.color.tertiary;
MOV result.color, fragment.color;
END
