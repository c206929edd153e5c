// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.5: "struct gl_DepthRangeParameters { float near; float far; float diff; };" (fields are near/far/diff, not nearVal)
#version 110
void main()
{
    gl_Position = vec4(gl_DepthRange.nearVal);
}
