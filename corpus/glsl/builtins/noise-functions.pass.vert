// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 8.9: "Noise functions are available to both fragment and vertex shaders." "float noise1 (genType x)", "vec2 noise2", "vec3 noise3", "vec4 noise4"
void main()
{
    vec4 p = gl_Vertex;
    float a = noise1(p.x) + noise1(p.xy) + noise1(p.xyz) + noise1(p);
    vec2 b = noise2(p);
    vec3 c = noise3(p.xy);
    vec4 d = noise4(p.x);
    gl_Position = ftransform() + vec4(c, a) + d + vec4(b, b);
}
