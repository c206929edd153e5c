// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.5: "To form an r-value, it can be applied to any expression that results in a vector r-value."
vec4 color()
{
    return vec4(0.1, 0.2, 0.3, 0.4);
}
void main()
{
    gl_FragColor = vec4(color().zyx, vec4(1.0).w);
}
