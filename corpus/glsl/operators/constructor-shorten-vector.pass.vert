// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.4.2: "vec2(vec3) // drops the third component of a vec3" and "vec3(vec4) // drops the fourth component of a vec4"
uniform vec4 c;
void main()
{
    vec3 rgb = vec3(c);
    vec2 xy = vec2(rgb);
    gl_Position = vec4(xy, rgb.z, 1.0);
}
