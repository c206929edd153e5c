!!ARBfp1.0
MOV result.color, fragment.color;
ADD result.depth.z, fragment.texcoord[0].y, fragment.position.z;
END
