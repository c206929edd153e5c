!!ARBfp1.0
# texture[4]: beyond the minimum of 2 texture image units (ARBfp 3.11.2 <texImageUnitNum>)
# no warning by default (Mesa takes it); --limits spec-min rejects it
TEMP base;
TEX base, fragment.texcoord[0], texture[4], 2D;
MUL result.color, base, fragment.color;
END
