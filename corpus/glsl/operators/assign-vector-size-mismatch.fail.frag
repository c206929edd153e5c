// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.8: "It will compile only if expression and lvalue have the same type."
uniform vec4 c;
void main()
{
    vec3 v;
    v = c;
    gl_FragColor = vec4(v, 1.0);
}
