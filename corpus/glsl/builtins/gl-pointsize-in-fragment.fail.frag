// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.1: "The variable gl_PointSize is available only in the vertex language"
#version 110
void main()
{
    gl_FragColor = vec4(gl_PointSize);
}
