!!ARBfp1.0
# SCS writing z and w: those components of SCS are undefined (ARBfp 3.11.5.23)
# EXPECT-WARNING: 5:5 arb-undefined-result
TEMP cs;
SCS cs, program.local[0].x;
MOV result.color, cs;
END
