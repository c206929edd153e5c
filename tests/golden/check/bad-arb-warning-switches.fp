!!ARBfp1.0
# ARGS: -Wno-arb-temp-uninitialized -Werror=arb-undefined-result
# -W<code> switches work on ARB warnings: one silenced, one made an error
TEMP t, u;
SCS t, fragment.texcoord[0].x;
ADD result.color, t, u;
END
