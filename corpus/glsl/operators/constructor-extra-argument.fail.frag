// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.4.2: "It is an error to provide extra arguments beyond this last used argument."
uniform vec2 a;
uniform vec2 b;
void main()
{
    vec3 v = vec3(a, b, 1.0);
    gl_FragColor = vec4(v, 1.0);
}
