// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.4.2: "Constructors can be used to create vectors or matrices from a set of scalars, vectors, or matrices."
uniform mat2 m;
void main()
{
    vec4 v = vec4(m);
    gl_FragColor = v;
}
