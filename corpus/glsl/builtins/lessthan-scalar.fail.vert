// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.6: ""vec" is a placeholder for vec2, vec3, or vec4" (no scalar overloads; use the < operator for scalars)
uniform float a;
uniform float b;
void main()
{
    bool r = lessThan(a, b);
    gl_Position = vec4(float(r));
}
