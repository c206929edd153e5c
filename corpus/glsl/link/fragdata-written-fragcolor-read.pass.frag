// [config]
// expect_result: pass
// glsl_version: 1.10
// check_link: true
// [end config]
// Section 7.2: "If a shader statically writes a value to any element of gl_FragData, it may not assign a value to gl_FragColor." (only assignments are restricted; reading gl_FragColor gives an undefined value but is legal)
#version 110
void main()
{
    gl_FragData[0] = vec4(0.5);
    gl_FragData[0] = gl_FragData[0] + gl_FragColor * 0.0;
}
