// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "#extension extension_name : behavior / #extension all : behavior" (behavior: require, enable, warn, disable)
// 3.3 "The initial state of the compiler is as if the directive #extension all : disable was issued"
#version 110
#extension all : disable
void main()
{
    gl_Position = vec4(0.0);
}
