// [config]
// expect_result: fail
// glsl_version: 1.10
// check_link: true
// [end config]
// Section 7.2: "If a shader statically assigns a value to gl_FragColor, it may not assign a value to any element of gl_FragData."
void main()
{
    gl_FragColor = vec4(1.0);
    gl_FragData[0] = vec4(0.0);
}
