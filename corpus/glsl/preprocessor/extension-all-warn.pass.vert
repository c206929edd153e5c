// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "#extension extension_name : behavior / #extension all : behavior" (behavior: require, enable, warn, disable)
#version 110
#extension all : warn
void main()
{
    gl_Position = vec4(0.0);
}
