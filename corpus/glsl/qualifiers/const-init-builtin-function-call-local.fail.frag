// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3.2 "Constructors may be used in such expressions, but function calls may not."
void main()
{
    const vec3 n = normalize(vec3(1.0, 0.0, 0.0));
    gl_FragColor = vec4(n, 1.0);
}
