// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: increment needs "an l-value"; 5.8: "swizzles with repeated fields ... cannot be l-values."
void main()
{
    vec4 v = vec4(0.0);
    v.xx++;
    gl_FragColor = v;
}
