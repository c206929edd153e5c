// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.4.2: "there must be enough components provided in the parameters to provide an initializer for every component in the constructed value."
uniform vec2 a;
void main()
{
    gl_Position = vec4(a, 1.0);
}
