// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.4.2: "If there is a single scalar parameter to a vector constructor, it is used to initialize all components of the constructed vector to that scalar's value."
void main()
{
    vec4 a = vec4(0.5);
    ivec3 b = ivec3(2);
    bvec2 c = bvec2(true);
    gl_FragColor = a + vec4(float(b.z), float(c.y), 0.0, 0.0);
}
