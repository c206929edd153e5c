!!ARBfp1.0
# PARAM array size 5 bound to a four-entry env range (ARBfp 3.11.3.2)
# FAIL
# EXPECT-ERROR: 5:9 arb-param-array-size
PARAM e[5] = { program.env[0..3] };
MOV result.color, fragment.color;
END
