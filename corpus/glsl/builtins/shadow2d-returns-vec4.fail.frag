// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.7: "vec4 shadow2D (sampler2DShadow sampler, vec3 coord [, float bias] )" (the result is a vec4, not a float)
#version 110
uniform sampler2DShadow s;
void main()
{
    float d = shadow2D(s, gl_TexCoord[0].xyz);
    gl_FragColor = vec4(d);
}
