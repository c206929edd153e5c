// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.7 "They can only be declared as function parameters or uniforms"
// 4.3.6 "The varying qualifier can be used only with the data types float, vec2, vec3, vec4, mat2, mat3, and mat4, or arrays of these."
varying sampler2D tex;
void main()
{
    gl_FragColor = texture2D(tex, vec2(0.5));
}
