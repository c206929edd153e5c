// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.4: "vec4 ftransform() For vertex shaders only."
void main()
{
    gl_FragColor = ftransform();
}
