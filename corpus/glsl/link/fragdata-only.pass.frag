// [config]
// expect_result: pass
// glsl_version: 1.10
// check_link: true
// [end config]
// Section 7.2: "a shader may assign values to either gl_FragColor or gl_FragData, but not both."
#version 110
void main()
{
    gl_FragData[0] = vec4(0.0);
    gl_FragData[0].a = 1.0;
}
