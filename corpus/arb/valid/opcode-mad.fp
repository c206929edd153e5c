!!ARBfp1.0
# MAD and MAD_SAT: multiply and add (ARBfp 3.11.5.15)
# Quake-style lightmapping with overbright: base * lightmap * 2 + emissive.
TEMP base, lmap;
TEX base, fragment.texcoord[0], texture[0], 2D;
TEX lmap, fragment.texcoord[1], texture[1], 2D;
MUL lmap, lmap, 2.0;
MAD_SAT result.color.rgb, base, lmap, state.material.emission;
MAD result.color.a, base.a, fragment.color.a, 0.0;
END
