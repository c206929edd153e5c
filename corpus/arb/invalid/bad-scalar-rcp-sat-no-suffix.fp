!!ARBfp1.0
# RCP_SAT needs a scalar operand too (ARBfp 3.11.2 <SCALARop>)
# FAIL
# EXPECT-ERROR: 6:12 arb-operand-scalar
TEMP r;
RCP_SAT r, fragment.fogcoord;
MOV result.color, fragment.color;
END
