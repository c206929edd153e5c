!!ARBfp1.0
# the largest colour channel kept, the others zeroed, after Mesa's demos (SGE R0,
# fragment.color, fragment.color.yzxw): the product of two SGE results is the branch-free
# "and" (ARBfp 3.11.5.19: multiplication by zero and one "may be used to evaluate
# conditional expressions without branching")
TEMP R0, R1;
SGE R0, fragment.color, fragment.color.yzxw;
SGE R1, fragment.color, fragment.color.zxyw;
MUL R0, R0, R1;
MUL result.color, R0, fragment.color;
END
