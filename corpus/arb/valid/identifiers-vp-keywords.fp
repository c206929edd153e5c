!!ARBfp1.0
# vertex-program keywords are not reserved in a fragment program: vertex, ADDRESS, ARL, EXP, LOG (ARBfp 3.11.2 reserved list)
TEMP vertex, ADDRESS, ARL, EXP, LOG;
MOV vertex, fragment.color;
MOV ADDRESS, vertex;
MOV ARL, ADDRESS;
MOV EXP, ARL;
MOV LOG, EXP;
MOV result.color, LOG;
END
