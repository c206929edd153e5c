!!ARBfp1.0
# seventeen temporaries: beyond the minimum MAX_PROGRAM_TEMPORARIES_ARB of 16 (ARBfp 3.11.3.6)
# no warning by default (Mesa takes it); --limits spec-min rejects it
TEMP t0, t1, t2, t3, t4, t5, t6, t7, t8, t9, t10, t11, t12, t13, t14, t15, t16;
MOV t0, fragment.color;
MOV t1, t0;
MOV t2, t1;
MOV t3, t2;
MOV t4, t3;
MOV t5, t4;
MOV t6, t5;
MOV t7, t6;
MOV t8, t7;
MOV t9, t8;
MOV t10, t9;
MOV t11, t10;
MOV t12, t11;
MOV t13, t12;
MOV t14, t13;
MOV t15, t14;
MOV t16, t15;
MOV result.color, t16;
END
