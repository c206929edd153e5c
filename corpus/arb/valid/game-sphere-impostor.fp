!!ARBfp1.0
# sphere impostor: KIL outside the disc and write result.depth (ARBfp 3.11.3.4, 3.11.6.4)
# texcoord 0: quad position in [-1,1]^2; texcoord 1.x: sphere radius in window depth units.
TEMP p, d;
MUL p.xy, fragment.texcoord[0], fragment.texcoord[0];
ADD p.z, p.x, p.y;
SUB p.z, 1.0, p.z;                      # 1 - x^2 - y^2
KIL p.z;                                # outside the disc
RSQ p.w, p.z;
MUL p.z, p.z, p.w;                      # sqrt(1 - x^2 - y^2)
MAD d.z, -p.z, fragment.texcoord[1].x, fragment.position.z;
MOV result.depth.z, d.z;
MUL result.color, fragment.color, p.z;
END
