// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.3: "except in the do-while loop, which cannot declare a variable in its condition-expression."
void main()
{
    int n = 0;
    do {
        n++;
    } while (bool more = n < 3);
    gl_FragColor = vec4(float(n));
}
