// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.2: "genType pow (genType x, genType y)"; 6.1: "No promotion or demotion of the return type or input argument types is done."
uniform float f;
void main()
{
    gl_FragColor = vec4(pow(f, 2));
}
