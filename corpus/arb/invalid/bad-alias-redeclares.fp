!!ARBfp1.0
# an ALIAS whose new name is already declared (ARBfp 3.11.3.5: the left side must be new)
# FAIL
# EXPECT-ERROR: 6:7 arb-decl-redeclared
TEMP a, b;
ALIAS a = b;
MOV result.color, fragment.color;
END
