// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.5: "vec2 pos; pos.x // is legal"
uniform vec2 pos;
void main()
{
    float x = pos.x + pos.g + pos.t;
    gl_Position = vec4(pos.yx, x, 1.0);
}
