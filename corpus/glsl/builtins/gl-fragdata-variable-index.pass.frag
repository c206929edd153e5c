// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 7.2: "vec4 gl_FragData[gl_MaxDrawBuffers];" (a sized array; 4.1.9 allows a non-constant index into a sized array)
uniform int target;
void main()
{
    gl_FragData[target] = vec4(1.0);
}
