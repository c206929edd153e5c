!!ARBfp1.0
# KIL on a whole interpolated vector: any negative component discards the fragment, NaN
# and -0 do not (ARBfp 3.11.5.11).
KIL fragment.texcoord[0];
MOV result.color, fragment.color;
END
