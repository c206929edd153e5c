// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.3: "smoothstep (genType edge0, genType edge1, genType x)" and "smoothstep (float edge0, float edge1, genType x)"
#version 110
uniform vec2 v;
void main()
{
    gl_Position = vec4(smoothstep(v, 1.0, v), 0.0, 1.0);
}
