// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.2: "vec4 gl_FragData[gl_MaxDrawBuffers];"; 4.1.9: "It is illegal to declare an array with a size, and then later (in the same shader) index the same array with an integral constant expression greater than or equal to the declared size."
#version 110
void main()
{
    gl_FragData[gl_MaxDrawBuffers] = vec4(1.0);
}
