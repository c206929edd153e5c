!!ARBfp1.0
# all fifteen rgba write masks in the order the grammar lists them (ARBfp 3.11.4.3)
TEMP m;
MOV m, 1.0;
MUL m.r, m, fragment.color;
MUL m.g, m, fragment.color;
MUL m.rg, m, fragment.color;
MUL m.b, m, fragment.color;
MUL m.rb, m, fragment.color;
MUL m.gb, m, fragment.color;
MUL m.rgb, m, fragment.color;
MUL m.a, m, fragment.color;
MUL m.ra, m, fragment.color;
MUL m.ga, m, fragment.color;
MUL m.rga, m, fragment.color;
MUL m.ba, m, fragment.color;
MUL m.rba, m, fragment.color;
MUL m.gba, m, fragment.color;
MUL m.rgba, m, fragment.color;
MOV result.color.rgb, m;
MOV result.color.a, m.a;
END
