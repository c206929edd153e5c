!!ARBfp1.0
# state.texenv[2].color: beyond the minimum of 2 legacy texture units (ARBfp 3.11.3.2, Table X.2.4)
# no warning by default (Mesa takes it); --limits spec-min rejects it
MUL result.color, fragment.color, state.texenv[2].color;
END
