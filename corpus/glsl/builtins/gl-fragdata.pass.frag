// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 7.2: "Writing to gl_FragData[n] specifies the fragment data that will be used by the subsequent fixed functionality pipeline for data n."
void main()
{
    gl_FragData[0] = vec4(1.0, 0.0, 0.0, 1.0);
}
