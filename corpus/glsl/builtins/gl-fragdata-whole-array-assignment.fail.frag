// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.2: "Writing to gl_FragData[n] specifies the fragment data ..."; 5.8: "non-dereferenced arrays ... cannot be l-values."
#version 110
void main()
{
    vec4 d[gl_MaxDrawBuffers];
    gl_FragData = d;
}
