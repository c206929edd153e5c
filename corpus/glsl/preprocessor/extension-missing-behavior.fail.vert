// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "#extension extension_name : behavior / #extension all : behavior" (behavior: require, enable, warn, disable)
#extension GL_ARB_texture_rectangle
void main()
{
    gl_Position = vec4(0.0);
}
