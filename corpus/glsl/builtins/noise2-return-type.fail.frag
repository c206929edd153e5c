// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.9: "vec2 noise2 (genType x)"
void main()
{
    vec3 n = noise2(gl_TexCoord[0]);
    gl_FragColor = vec4(n, 1.0);
}
