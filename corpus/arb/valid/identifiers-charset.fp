!!ARBfp1.0
# identifiers with letters, digits, _ and $, case-sensitive, and non-reserved look-alikes (ARBfp 3.11.2 <identifier>)
TEMP _tmp, $x, a1_b2$, Temp, temp, TEMP_2;
TEMP color, texcoord, position, tex, mov, Texture, Result, END_1, matrix;
MOV _tmp, fragment.color;
MOV $x, _tmp;
MOV a1_b2$, $x;
MOV Temp, a1_b2$;
MOV temp, Temp;
MOV TEMP_2, temp;
MOV color, TEMP_2;
MOV texcoord, color;
MOV position, texcoord;
MOV tex, position;
MOV mov, tex;
MOV Texture, mov;
MOV Result, Texture;
MOV END_1, Result;
MOV matrix, END_1;
MOV result.color, matrix;
END
