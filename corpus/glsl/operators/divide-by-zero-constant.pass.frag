// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.9: "Dividing by zero does not cause an exception but does result in an unspecified value."
#version 110
void main()
{
    float f = 1.0 / 0.0;
    int i = 1 / 0;
    gl_FragColor = vec4(f, float(i), 0.0, 1.0);
}
