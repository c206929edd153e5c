!!ARBfp1.0
# ARGS: --format json --vectors kil.json
# KIL discards when any component < 0; NaN does not kill (3.11.6.4).
KIL fragment.texcoord[0];
MOV result.color, fragment.texcoord[0];
END
