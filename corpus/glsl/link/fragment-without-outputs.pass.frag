// [config]
// expect_result: pass
// glsl_version: 1.10
// check_link: true
// [end config]
// Section 7.2: "If subsequent fixed functionality consumes fragment color and an execution of a fragment shader does not write a value to gl_FragColor then the fragment color consumed is undefined." (undefined, not an error)
uniform float u;
void main()
{
    float unused = u * 2.0;
}
