// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.4: "the function name is a basic-type keyword or structure name"; grammar constructor_identifier lists only basic types and TYPE_NAME (no array constructors in 1.10); 4.1.9: "There is no mechanism for initializing arrays at declaration time from within a shader."
#version 110
void main()
{
    float a[2];
    a = float[2](1.0, 2.0);
    gl_Position = vec4(a[0]);
}
