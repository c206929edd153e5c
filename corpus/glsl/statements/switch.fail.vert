// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 9: "// Grammar Note: No 'switch'. Switch statements not supported." (switch, case, default are reserved keywords, 3.6)
uniform int k;
void main()
{
    float f = 0.0;
    switch (k) {
    case 0: f = 1.0; break;
    default: f = 2.0;
    }
    gl_Position = vec4(f);
}
