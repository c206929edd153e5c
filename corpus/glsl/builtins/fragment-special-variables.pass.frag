// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 7.2: "vec4 gl_FragCoord; bool gl_FrontFacing; vec4 gl_FragColor; vec4 gl_FragData[gl_MaxDrawBuffers]; float gl_FragDepth;"
#version 110
void main()
{
    vec4 c = gl_FrontFacing ? vec4(1.0) : vec4(0.5);
    gl_FragColor = c * gl_FragCoord.x;
    gl_FragDepth = gl_FragCoord.z;
    gl_FragColor.a = gl_FragColor.a + gl_FragDepth;
}
