// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.5: "{x, y, z, w} ... {r, g, b, a} ... {s, t, p, q}"; "v4.rgba; // is a vec4 ... v4.b; // is a float"
#version 110
uniform vec4 v4;
void main()
{
    vec4 a = v4.rgba;
    vec3 b = v4.stp;
    vec2 c = v4.xy;
    float d = v4.b + v4.q + v4.w;
    gl_FragColor = a + vec4(b, d) + vec4(c, c);
}
