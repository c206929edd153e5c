!!ARBfp1.0
# result.color[8]: beyond MAX_DRAW_BUFFERS_ARB (8 on Mesa) (ARB_draw_buffers)
# FAIL
# EXPECT-ERROR: 7:18 arb-binding-index-range
OPTION ARB_draw_buffers;
MOV result.color[0], fragment.color;
MOV result.color[8], fragment.color.secondary;
END
