!!ARBfp1.0
# ADD and ADD_SAT: component-wise addition (ARBfp 3.11.5.2)
# Base texture plus a glow map plus the secondary (specular) colour.
TEMP base, glow;
TEX base, fragment.texcoord[0], texture[0], 2D;
TEX glow, fragment.texcoord[1], texture[1], 2D;
ADD base, base, glow;
ADD_SAT result.color.rgb, base, fragment.color.secondary;
MOV result.color.a, base.a;
END
