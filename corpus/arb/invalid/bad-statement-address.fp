!!ARBfp1.0
# ADDRESS declarations exist only in vertex programs (ARBfp 3.11.2 <namingStatement>)
# FAIL
# EXPECT-ERROR: 5:1 arb-syntax-statement-stage
ADDRESS a0;
MOV result.color, fragment.color;
END
