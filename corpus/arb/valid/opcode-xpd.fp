!!ARBfp1.0
# XPD and XPD_SAT: cross product, w left unwritten (ARBfp 3.11.5.29)
# Rebuild the bitangent from normal (texcoord 0) and tangent (texcoord 1).
TEMP bt, c;
XPD bt.xyz, fragment.texcoord[0], fragment.texcoord[1];
MOV bt.w, 1.0;
XPD_SAT c.xyz, bt, fragment.texcoord[0];
MOV c.w, fragment.color.a;
MAD result.color, bt, 0.5, c;
END
