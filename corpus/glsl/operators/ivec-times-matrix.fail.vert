// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: "for multiply (*), one can be a vector and the other a matrix"; "the left argument is a floating-point vector and the right is a matrix" (an integer vector does not qualify)
uniform mat2 m;
uniform ivec2 v;
void main()
{
    vec2 r = v * m;
    gl_Position = vec4(r, 0.0, 1.0);
}
