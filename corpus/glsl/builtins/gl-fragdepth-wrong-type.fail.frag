// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.2: "float gl_FragDepth;"; 5.8: assignment needs the same type
#version 110
void main()
{
    gl_FragColor = vec4(1.0);
    gl_FragDepth = gl_FragCoord;
}
