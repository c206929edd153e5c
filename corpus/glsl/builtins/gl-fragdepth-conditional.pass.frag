// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 7.2: "If a shader statically assigns a value to gl_FragDepth, and there is an execution path through the shader that does not set gl_FragDepth, then the value of the fragment's depth may be undefined" (undefined, not an error)
uniform bool deep;
void main()
{
    if (deep)
        gl_FragDepth = 1.0;
    gl_FragColor = vec4(1.0);
}
