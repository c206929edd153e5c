// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.2/5.5/5.6: the subscript operator applies to arrays, vectors and matrices; a scalar float has no elements
#version 110
uniform float f;
void main()
{
    gl_FragColor = vec4(f[0]);
}
