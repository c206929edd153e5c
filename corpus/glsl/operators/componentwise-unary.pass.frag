// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.10: "All unary operations work component-wise on their operands."
#version 110
uniform vec4 a;
uniform mat3 m;
uniform ivec2 i;
void main()
{
    vec4 n = -a;
    mat3 k = -m;
    ivec2 j = -i;
    gl_FragColor = n + vec4(k[0], float(j.y));
}
