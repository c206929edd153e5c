!!ARBfp1.0
# state.depth.range (near, far, far-near, 1) (ARBfp 3.11.3.2, Table X.2.6)
# Visualize the window depth normalized to the depth range.
PARAM range = state.depth.range;
TEMP d;
SUB d.x, fragment.position.z, range.x;
RCP d.y, range.z;
MUL_SAT d.x, d.x, d.y;
MOV result.color, d.x;
END
