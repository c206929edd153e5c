// [config]
// expect_result: fail
// glsl_version: 1.20
// [end config]
// EXT_texture_array: the array sampler types and functions exist only where "#extension GL_EXT_texture_array" enables them
#version 120
uniform sampler2DArray layers;
void main()
{
    gl_FragColor = texture2DArray(layers, vec3(0.0));
}
