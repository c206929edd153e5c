!!ARBfp1.0
# naïve comment: arbiter warns, the program is still accepted
MOV result.color, fragment.color;
END
