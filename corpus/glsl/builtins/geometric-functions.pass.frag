// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 8.4: "float length (genType x)", "float distance (genType p0, genType p1)", "float dot", "vec3 cross (vec3 x, vec3 y)", "normalize", "faceforward", "reflect", "refract(genType I, genType N, float eta)"
uniform vec3 a;
uniform vec3 b;
uniform vec2 c;
void main()
{
    float l = length(a) + length(c) + length(1.0) + distance(a, b) + dot(a, b) + dot(c, c);
    vec3 x = cross(a, b) + normalize(a) + faceforward(a, b, a) + reflect(a, b) + refract(a, b, 0.5);
    vec2 y = refract(c, c, 1.33);
    gl_FragColor = vec4(x * l, y.x);
}
