// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.5: "To form an l-value, swizzling must be applied to an l-value of vector type, contain no duplicate components, and results in an l-value of scalar or vector type"
void main()
{
    vec4 v = vec4(0.0);
    v.zyx.xy = vec2(1.0, 2.0);
    v.wzyx.w = 3.0;
    gl_Position = v;
}
