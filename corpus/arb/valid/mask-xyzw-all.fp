!!ARBfp1.0
# all fifteen xyzw write masks in the order the grammar lists them (ARBfp 3.11.4.3)
TEMP m;
MOV m, 0.0;
MOV m.x, fragment.color.x;
MOV m.y, fragment.color.y;
MOV m.xy, fragment.color;
MOV m.z, fragment.color.z;
MOV m.xz, fragment.color;
MOV m.yz, fragment.color;
MOV m.xyz, fragment.color;
MOV m.w, fragment.color.w;
MOV m.xw, fragment.color;
MOV m.yw, fragment.color;
MOV m.xyw, fragment.color;
MOV m.zw, fragment.color;
MOV m.xzw, fragment.color;
MOV m.yzw, fragment.color;
MOV m.xyzw, fragment.color;
MOV result.color.xyzw, m;
END
