!!ARBfp1.0
# NV_fragment_program2: inside LOOP, fragment.texcoord[A0.x+n] reads the texture coordinate
# set A0.x + n with the loop index A0.x (3.11.3.1, 3.11.3.Y). The loop {3, 0, 1} runs
# A0.x = 0, 1, 2, so this sums sets 1, 2 and 3.
OPTION NV_fragment_program2;
TEMP sum;
MOV sum, {0, 0, 0, 0};
LOOP {3, 0, 1};
ADD sum, sum, fragment.texcoord[A0.x + 1];
ENDLOOP;
MOV result.color, sum;
END
