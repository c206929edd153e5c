// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.4: "vec3 cross (vec3 x, vec3 y)" (vec3 only)
uniform vec4 a;
uniform vec4 b;
void main()
{
    gl_FragColor = vec4(cross(a, b), 1.0);
}
