!!ARBfp1.0
# the smallest program: header and END only (ARBfp 3.11.2 <program>)
END
