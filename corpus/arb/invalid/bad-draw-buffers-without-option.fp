!!ARBfp1.0
# result.color[1] without OPTION ARB_draw_buffers (ARB_draw_buffers)
# FAIL
# EXPECT-ERROR: 6:18 arb-option-required
MOV result.color, fragment.color;
MOV result.color[1], fragment.color.secondary;
END
