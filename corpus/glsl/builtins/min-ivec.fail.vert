// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.3: "genType min (genType x, genType y)", "genType min (genType x, float y)" (genType is a float type)
#version 110
uniform ivec2 a;
uniform ivec2 b;
void main()
{
    ivec2 m = min(a, b);
    gl_Position = vec4(float(m.x));
}
