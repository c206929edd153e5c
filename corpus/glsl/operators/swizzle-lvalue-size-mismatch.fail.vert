// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.5: "pos.xy = vec3(1.0, 2.0, 3.0);// illegal - mismatch between vec2 and vec3"
void main()
{
    vec4 pos = vec4(1.0, 2.0, 3.0, 4.0);
    pos.xy = vec3(1.0, 2.0, 3.0);
    gl_Position = pos;
}
