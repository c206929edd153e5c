// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.6: "The components of a matrix can be accessed using array subscripting syntax." (5.5 swizzles apply to vectors only)
uniform mat2 m;
void main()
{
    vec2 v = m.xy;
    gl_FragColor = vec4(v, 0.0, 1.0);
}
