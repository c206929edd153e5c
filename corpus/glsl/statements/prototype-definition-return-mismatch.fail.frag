// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.1: "If functions' names and argument types match, then their return type and parameter qualifiers must also match."
float get(float x);
vec2 get(float x)
{
    return vec2(x);
}
void main()
{
    gl_FragColor = vec4(1.0);
}
