!!ARBfp1.0
# negated and explicitly positive operands of every register kind (ARBfp 3.11.4.1 <optionalSign>)
TEMP a, b;
MOV a, -fragment.color;
ADD a, a, -program.local[0];
MAD b, -a.x, -fragment.texcoord[0].yxzw, -{ 0.5, 0.25, 0, 1 };
ADD b, b, -0.5;
SUB b, -b, +a;
MUL b, b, -state.material.diffuse;
ADD result.color, -b, +fragment.color.secondary;
END
