!!ARBfp1.0
# projected spotlight: TXP cookie and 1D distance falloff (ARBfp 3.11.6.2)
TEMP cookie, falloff, c;
TXP cookie, fragment.texcoord[0], texture[0], 2D;
TEX falloff, fragment.texcoord[1], texture[1], 1D;
MUL c, cookie, falloff.x;
MUL result.color, c, fragment.color;
END
