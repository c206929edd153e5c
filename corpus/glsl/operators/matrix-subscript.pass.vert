// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.6: "m[1] = vec4(2.0); // sets the second column to all 2.0", "m[0][0] = 1.0;", "m[2][3] = 2.0;"
void main()
{
    mat4 m = mat4(0.0);
    m[1] = vec4(2.0);
    m[0][0] = 1.0;
    m[2][3] = 2.0;
    m[3].xy = vec2(0.5);
    gl_Position = m[1] + vec4(m[2].w);
}
