!!ARBfp1.0
# names are case-sensitive: Base is not base (ARBfp 3.11.2 <identifier>)
# FAIL
# EXPECT-ERROR: 7:19 arb-decl-undeclared
TEMP base;
TEX base, fragment.texcoord[0], texture[0], 2D;
MOV result.color, Base;
END
