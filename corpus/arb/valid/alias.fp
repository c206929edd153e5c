!!ARBfp1.0
# ALIAS of a temporary, a parameter, an attribute, an output and an alias (ARBfp 3.11.3.5)
TEMP work;
PARAM tint = program.local[0];
ATTRIB uv = fragment.texcoord[0];
OUTPUT outColor = result.color;
ALIAS base = work;
ALIAS tintAlias = tint;
ALIAS coord = uv;
ALIAS dst = outColor;
ALIAS base2 = base;
TEX base, coord, texture[0], 2D;
MUL base2, work, tintAlias;
MOV dst, base;
END
