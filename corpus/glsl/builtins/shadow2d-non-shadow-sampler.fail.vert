// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.7: "vec4 shadow2D (sampler2DShadow sampler, vec3 coord [, float bias] )"
uniform sampler2D s;
void main()
{
    gl_Position = shadow2D(s, gl_MultiTexCoord0.xyz);
}
