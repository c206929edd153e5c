// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.4: "genType refract(genType I, genType N, float eta)"
#version 110
uniform vec3 i;
uniform vec3 n;
void main()
{
    gl_Position = vec4(refract(i, n, vec3(0.5)), 1.0);
}
