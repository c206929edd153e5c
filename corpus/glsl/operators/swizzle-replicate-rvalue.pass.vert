// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.5: "vec4 swiz = pos.wzyx;" and "vec4 dup = pos.xxyy;" and "To form an r-value, it can be applied to any expression that results in a vector r-value."
void main()
{
    vec4 pos = vec4(1.0, 2.0, 3.0, 4.0);
    vec4 swiz = pos.wzyx;
    vec4 dup = pos.xxyy;
    vec2 e = (swiz + dup).zw;
    vec2 k = vec4(0.5).xy;
    gl_Position = vec4(e, k);
}
