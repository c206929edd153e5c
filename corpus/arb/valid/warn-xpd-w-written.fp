!!ARBfp1.0
# XPD writing w: the w component of a cross product is undefined (ARBfp 3.11.5.29)
# EXPECT-WARNING: 5:5 arb-undefined-result
TEMP bt;
XPD bt, fragment.texcoord[0], fragment.texcoord[1];
MOV result.color, bt;
END
