// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.3 lists abs, sign, floor, ceil, fract, mod, min, max, clamp, mix, step, smoothstep; round (GLSL 1.30) is not a 1.10 built-in
uniform float f;
void main()
{
    gl_FragColor = vec4(round(f));
}
