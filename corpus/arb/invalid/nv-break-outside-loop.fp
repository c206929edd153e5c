!!ARBfp1.0
# BRK leaves a LOOP or REP block; outside one it has nowhere to go (NV_fragment_program2 3.11.5, BRK)
# FAIL
# EXPECT-ERROR: 8:1 arb-flow-break-outside-loop
OPTION NV_fragment_program2;
TEMP t;
MOVC t, fragment.color;
BRK (GT.x);
MOV result.color, t;
END
