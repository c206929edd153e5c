!!ARBfp1.0
# KIL operands: attribute, negated, swizzled, parameter, inline constant (ARBfp 3.11.6.4)
TEMP t;
KIL fragment.texcoord[0];
KIL -fragment.texcoord[1].wzyx;
KIL fragment.color.a;
KIL program.local[0];
KIL { 1, 0.5, 0, 1 };
KIL -state.fog.color.x;
MOV t, fragment.color;
KIL t.xyzx;
MOV result.color, t;
END
