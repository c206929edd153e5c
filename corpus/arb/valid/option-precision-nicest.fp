!!ARBfp1.0
# OPTION ARB_precision_hint_nicest (ARBfp 3.11.4.5.2)
OPTION ARB_precision_hint_nicest;
TEMP n;
DP3 n.x, fragment.texcoord[0], fragment.texcoord[0];
RSQ n.x, n.x;
MUL result.color, fragment.texcoord[0], n.x;
END
