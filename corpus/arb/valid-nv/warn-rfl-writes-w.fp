!!ARBfp1.0
# RFL with w in its write mask: NV_fragment_program says the program fails to load, NVIDIA's drivers (and piglit) load it; w is undefined (NV_fragment_program 3.11.5, RFL)
# EXPECT-WARNING: 6:5 arb-rfl-writes-w
OPTION NV_fragment_program;
TEMP r;
RFL r, fragment.texcoord[0], fragment.texcoord[1];
MOV result.color, r;
END
