// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.2: "Vector types are not accepted as the expression to if."
#version 110
uniform bvec2 p;
void main()
{
    vec4 c = vec4(0.0);
    if (p)
        c.x = 1.0;
    gl_FragColor = c;
}
