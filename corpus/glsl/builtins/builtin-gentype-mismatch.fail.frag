// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8: "For any specific use of a function, the actual type has to be the same for all arguments and for the return type."
uniform vec2 a;
uniform vec3 b;
void main()
{
    vec2 p = pow(a, b.xyz);
    gl_FragColor = vec4(p, 0.0, 1.0);
}
