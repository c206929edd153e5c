// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 1.10 4.3.5: "uniform ... variables ... cannot be initialized" ("initializers are not allowed on uniforms")
#version 110
uniform float u = 1.0;
void main()
{
    gl_FragColor = vec4(u);
}
