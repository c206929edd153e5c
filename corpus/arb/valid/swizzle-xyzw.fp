!!ARBfp1.0
# source swizzles with xyzw: identity, replicate, reverse, mixed (ARBfp 3.11.4.1)
TEMP a, b;
MOV a, fragment.texcoord[0].xyzw;
MOV b, fragment.texcoord[0].wzyx;
ADD a, a, b.xxyy;
MAD a, a.zwxy, b.y, fragment.color.yyyw;
MUL a, a, program.local[0].wwwx;
MOV b, a.z;
ADD result.color, a.xyzw, b.wyzx;
END
