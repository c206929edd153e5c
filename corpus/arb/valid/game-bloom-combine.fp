!!ARBfp1.0
# bloom combine: RECT scene plus scaled 2D bloom (ARBfp 3.11.6)
PARAM bloomStrength = program.env[4];
TEMP scene, bloom;
TEX scene, fragment.texcoord[0], texture[0], RECT;
TEX bloom, fragment.texcoord[1], texture[1], 2D;
MAD_SAT result.color, bloom, bloomStrength, scene;
END
