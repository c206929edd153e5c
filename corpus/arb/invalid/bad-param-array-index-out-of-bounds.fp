!!ARBfp1.0
# index 4 into a four-entry PARAM array (ARBfp 3.11.3.2: out-of-range access fails)
# FAIL
# EXPECT-ERROR: 6:39 arb-operand-index-range
PARAM pal[] = { program.env[0..3] };
MUL result.color, fragment.color, pal[4];
END
