!!ARBfp1.0
# LG2 and LG2_SAT: scalar base-2 logarithm (ARBfp 3.11.5.12)
# Gamma correction: c^gamma = 2^(gamma * log2 c) per channel.
PARAM gamma = program.env[0];
TEMP c, l;
TEX c, fragment.texcoord[0], texture[0], 2D;
LG2 l.x, c.r;
LG2 l.y, c.g;
LG2 l.z, c.b;
LG2_SAT l.w, c.a;
MUL l, l, gamma.x;
EX2 result.color.r, l.x;
EX2 result.color.g, l.y;
EX2 result.color.b, l.z;
MOV result.color.a, c.a;
END
