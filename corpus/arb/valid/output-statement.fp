!!ARBfp1.0
# OUTPUT names for result.color and result.depth (ARBfp 3.11.2 <OUTPUT_statement>)
OUTPUT oColor = result.color;
OUTPUT oDepth = result.depth;
TEMP base;
TEX base, fragment.texcoord[0], texture[0], 2D;
MUL oColor, base, fragment.color;
MOV_SAT oDepth.z, fragment.position.z;
END
