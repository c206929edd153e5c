// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.5: "v4.xgba; // is illegal - the component names do not come from the same set."
uniform vec4 v4;
void main()
{
    gl_FragColor = v4.xgba;
}
