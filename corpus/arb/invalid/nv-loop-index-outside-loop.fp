!!ARBfp1.0
# NV_fragment_program2 3.11.3.Y: "A fragment program that accesses A0.x outside a
# LOOP/ENDLOOP block will fail to load." (Inside REP there is no loop index either.)
# FAIL
# EXPECT-ERROR: 8:19 arb-flow-loop-index-outside-loop
OPTION NV_fragment_program2;
REP {2};
MOV result.color, fragment.texcoord[A0.x];
ENDREP;
END
