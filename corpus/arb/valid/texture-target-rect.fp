!!ARBfp1.0
# TEX with the RECT target addressed by window position (ARBfp 3.11.6)
# Screen-space copy of the frame with a refraction offset (heat haze).
TEMP offs, tc, scene;
TEX offs, fragment.texcoord[0], texture[0], 2D;
MAD offs, offs, 2.0, -1.0;
MAD tc, offs, program.local[0].x, fragment.position;
TEX scene, tc, texture[1], RECT;
MOV result.color, scene;
END
