!!ARBfp1.0
# an inline scalar constant as a scalar operand takes a component suffix (ARBfp 3.11.2 <scalarSrcReg>)
TEMP t;
RCP t.x, 0.5.x;
POW t.y, { 2, 3, 4, 5 }.w, 0.5.x;
SIN t.z, 3.0.x;
COS t.w, -1.5.x;
MUL result.color, t, fragment.color;
END
