!!ARBfp1.0
# source swizzles with rgba, and rgba next to xyzw in another operand (ARBfp 3.11.4.1)
TEMP c, d;
MOV c, fragment.color.rgba;
MOV d, fragment.color.secondary.abgr;
MUL c, c.rrgg, d.b;
MAD c, c.bgra, d.a, state.fog.color.rgbr;
ADD d, c.g, fragment.texcoord[0].xyzw;
LRP result.color, d.a, c.argb, d.bbba;
END
