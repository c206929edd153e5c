!!ARBfp1.0
# ENDIF closes an IF block; here there is none (NV_fragment_program2 3.11.2, IF/ELSE/ENDIF)
# FAIL
# EXPECT-ERROR: 7:1 arb-flow-unmatched
OPTION NV_fragment_program2;
MOV result.color, fragment.color;
ENDIF;
END
