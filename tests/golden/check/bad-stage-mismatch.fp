!!ARBfp1.0
# ARGS: --stage arbvp
MOV result.color, fragment.color;
END
