!!ARBfp1.0
# different targets on different units in one program: CUBE on 0, 3D on 1 (ARBfp 3.11.6)
TEMP env, noise;
TEX env, fragment.texcoord[0], texture[0], CUBE;
TEX noise, fragment.texcoord[1], texture[1], 3D;
MUL result.color, env, noise;
END
