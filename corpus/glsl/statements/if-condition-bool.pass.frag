// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 6.2: "Any expression whose type evaluates to a Boolean can be used as the conditional expression bool-expression."
uniform bool p;
uniform float f;
void main()
{
    vec4 c = vec4(0.0);
    if (p)
        c.x = 1.0;
    if (f > 0.5 && !p)
        c.y = 1.0;
    if (any(bvec2(p, false)))
        c.z = 1.0;
    gl_FragColor = c;
}
