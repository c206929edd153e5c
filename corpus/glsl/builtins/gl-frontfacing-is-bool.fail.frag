// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.2: "bool gl_FrontFacing;"; 5.8: assignment needs the same type
void main()
{
    float f = gl_FrontFacing;
    gl_FragColor = vec4(f);
}
