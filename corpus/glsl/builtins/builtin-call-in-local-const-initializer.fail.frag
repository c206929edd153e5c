// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 4.3.2: "Constructors may be used in such expressions, but function calls may not."
#version 110
void main()
{
    const vec3 n = normalize(vec3(1.0, 2.0, 3.0));
    gl_FragColor = vec4(n, 1.0);
}
