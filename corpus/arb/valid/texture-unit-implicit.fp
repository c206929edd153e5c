!!ARBfp1.0
# texture without [n] is unit 0, and texture[0] agrees with it (ARBfp 3.11.2 <optTexImageUnitNum>)
TEMP a, b;
TEX a, fragment.texcoord[0], texture, 2D;
TXP b, fragment.texcoord[1], texture[0], 2D;
ADD result.color, a, b;
END
