// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.5: "pos[2] refers to the third element of pos and is equivalent to pos.z. This allows variable indexing into a vector ... Any integer expression can be used as the subscript."
uniform int k;
void main()
{
    vec4 pos = vec4(1.0, 2.0, 3.0, 4.0);
    pos[2] = pos[k] + pos[0];
    gl_Position = pos;
}
