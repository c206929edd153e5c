// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.4 lists "gl_MaxVaryingFloats" for 1.10; gl_MaxVaryingComponents (GLSL 1.30) is not a 1.10 built-in
void main()
{
    gl_FragColor = vec4(float(gl_MaxVaryingComponents));
}
