// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.4: "float length (genType x)"
uniform vec3 a;
void main()
{
    vec3 l = length(a);
    gl_FragColor = vec4(l, 1.0);
}
