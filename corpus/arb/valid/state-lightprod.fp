!!ARBfp1.0
# state.lightprod[n] products, default, front and back (ARBfp 3.11.3.2, Table X.2.3)
TEMP nl, c, b;
DP3_SAT nl.x, fragment.texcoord[0], fragment.texcoord[1];
DP3_SAT nl.y, fragment.texcoord[0], state.light[0].half;
POW nl.y, nl.y, state.material.shininess.x;
MAD c, nl.x, state.lightprod[0].diffuse, state.lightprod[0].ambient;
MAD c, nl.y, state.lightprod[0].specular, c;
MAD c, nl.x, state.lightprod[1].front.diffuse, c;
ADD c, c, state.lightprod[1].front.ambient;
MAD c, nl.y, state.lightprod[1].front.specular, c;
MAD b, nl.x, state.lightprod[7].back.diffuse, state.lightprod[7].back.ambient;
MAD b, nl.y, state.lightprod[7].back.specular, b;
CMP result.color, program.local[0].x, b, c;
END
