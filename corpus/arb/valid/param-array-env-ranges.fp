!!ARBfp1.0
# PARAM arrays bound to program.env / program.local ranges, absolute indices (ARBfp 3.11.3.2, 3.11.4.2)
# A palette of eight tint colours and four blend weights set by the application.
PARAM palette[8] = { program.env[0..7] };
PARAM weights[] = { program.local[0..3] };
PARAM single[1] = { program.env[10..10] };
TEMP c;
MUL c, palette[0], weights[0].x;
MAD c, palette[1], weights[0].y, c;
MAD c, palette[2], weights[0].z, c;
MAD c, palette[3], weights[0].w, c;
MAD c, palette[4], weights[1], c;
MAD c, palette[5], weights[2], c;
MAD c, palette[6], weights[3], c;
MAD c, palette[7], single[0], c;
MUL result.color, c, fragment.color;
END
