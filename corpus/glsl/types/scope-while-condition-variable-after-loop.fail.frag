// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.2 "If it is declared in a while test or a for statement, then it is scoped to the end of the following sub-statement."
uniform float limit;
void main()
{
    float x = 0.0;
    while (bool more = x < limit)
        x += 1.0;
    gl_FragColor = vec4(more ? 1.0 : 0.0);
}
