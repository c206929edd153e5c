!!ARBfp1.0
# ARGS: --vectors 8 --engines ref,mesa-glsl --mutation lrp-operand-order --max-reports 2
# A translator bug injected (test-only): each disagreement with the engines' values and the
# inputs the program read.
LRP result.color, fragment.texcoord[0], fragment.color, program.local[0];
END
