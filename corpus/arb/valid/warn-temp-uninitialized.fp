!!ARBfp1.0
# a temporary read before any instruction writes it (ARBfp 3.11.3.3: temporaries start undefined)
# EXPECT-WARNING: 5:10 arb-temp-uninitialized
TEMP acc;
ADD acc, acc, fragment.color;
MOV result.color, acc;
END
