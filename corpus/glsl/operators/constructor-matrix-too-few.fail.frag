// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.4.2: "A wide range of other possibilities exist, as long as enough components are present to initialize the matrix."
#version 110
uniform vec4 v;
void main()
{
    mat3 n = mat3(v, v);
    gl_FragColor = vec4(n[0], 1.0);
}
