!!ARBfp1.0
# sixteen temporaries, the minimum MAX_PROGRAM_TEMPORARIES_ARB (ARBfp 3.11.3.6)
TEMP t0, t1, t2, t3, t4, t5, t6, t7;
TEMP t8, t9, t10, t11, t12, t13, t14, t15;
MOV t0, fragment.color;
ADD t1, t0, t0;
ADD t2, t1, t0;
ADD t3, t2, t1;
ADD t4, t3, t2;
ADD t5, t4, t3;
ADD t6, t5, t4;
ADD t7, t6, t5;
ADD t8, t7, t6;
ADD t9, t8, t7;
ADD t10, t9, t8;
ADD t11, t10, t9;
ADD t12, t11, t10;
ADD t13, t12, t11;
ADD t14, t13, t12;
ADD t15, t14, t13;
MUL result.color, t15, 0.001;
END
