// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.8: "the l-value and expression must satisfy the semantic requirements of both op and equals (=)." (mat3 * vec3 is a vec3, not a mat3)
uniform vec3 v;
void main()
{
    mat3 m = mat3(1.0);
    m *= v;
    gl_FragColor = vec4(m[0], 1.0);
}
