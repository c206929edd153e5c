!!ARBfp1.0
# TEX without a texture target (ARBfp 3.11.2 <SAMPLE_instruction>)
# FAIL
# EXPECT-ERROR: 5:51 arb-syntax-expected
TEX result.color, fragment.texcoord[0], texture[0];
END
