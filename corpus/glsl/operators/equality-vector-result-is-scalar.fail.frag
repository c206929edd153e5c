// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: equality operators "result in a scalar Boolean ... To get component-wise equality results for vectors, use the built-in functions equal and notEqual."
#version 110
uniform vec3 a;
uniform vec3 b;
void main()
{
    bvec3 e = a == b;
    gl_FragColor = vec4(float(e.x));
}
