!!ARBfp1.0
# state.light[n] properties: colours, position, attenuation, spot, half (ARBfp 3.11.3.2, Table X.2.3)
PARAM l0amb = state.light[0].ambient;
PARAM l0dif = state.light[0].diffuse;
PARAM l0spe = state.light[0].specular;
PARAM l0pos = state.light[0].position;
PARAM l0att = state.light[0].attenuation;
PARAM l0dir = state.light[0].spot.direction;
PARAM l0half = state.light[0].half;
PARAM l7dif = state.light[7].diffuse;
TEMP ldir, ndl, ndh, sp, c;
SUB ldir, l0pos, fragment.texcoord[1];
DP3 ndl.x, ldir, ldir;
RSQ ndl.x, ndl.x;
MUL ldir, ldir, ndl.x;
DP3 sp.x, -ldir, l0dir;                 # spot cosine
SGE sp.y, sp.x, l0dir.w;                # inside the cone
POW sp.z, sp.x, l0att.w;                # spot exponent
MUL sp.x, sp.y, sp.z;
DP3_SAT ndl.x, fragment.texcoord[0], ldir;
DP3_SAT ndh.x, fragment.texcoord[0], l0half;
POW ndh.x, ndh.x, program.local[1].x;
MAD c, ndl.x, l0dif, l0amb;
MAD c, ndh.x, l0spe, c;
MAD c, fragment.color, l7dif, c;
MUL result.color, c, sp.x;
END
