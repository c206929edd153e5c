!!ARBfp1.0
# TEX without a texture unit (ARBfp 3.11.2 <SAMPLE_instruction>)
# FAIL
# EXPECT-ERROR: 5:41 arb-syntax-expected
TEX result.color, fragment.texcoord[0], 2D;
END
