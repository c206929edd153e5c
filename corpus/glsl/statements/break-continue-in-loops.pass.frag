// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 6.4: "The continue jump is used only in loops." and "The break jump can also be used only in loops."
#version 110
void main()
{
    float s = 0.0;
    for (int i = 0; i < 8; i++) {
        if (i == 2)
            continue;
        if (i == 6)
            break;
        s += 1.0;
    }
    int n = 0;
    while (true) {
        n++;
        if (n > 3) break;
    }
    do {
        n--;
        if (n > 1) continue;
    } while (n > 0);
    gl_FragColor = vec4(s, float(n), 0.0, 1.0);
}
