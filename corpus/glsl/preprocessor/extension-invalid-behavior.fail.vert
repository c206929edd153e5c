// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "#extension extension_name : behavior / #extension all : behavior" (behavior: require, enable, warn, disable) ("The behavior can be one of the following")
#version 110
#extension all : on
void main()
{
    gl_Position = vec4(0.0);
}
