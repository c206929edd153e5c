!!ARBfp1.0
# program.env[250..256]: a range ending beyond the env parameters (ARBfp 3.11.2 <progEnvParamNums>)
# FAIL
# EXPECT-ERROR: 5:32 arb-binding-index-range
PARAM e[] = { program.env[250..256] };
MOV result.color, fragment.color;
END
