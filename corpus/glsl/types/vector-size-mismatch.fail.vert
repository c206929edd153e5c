// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.5 "The OpenGL Shading Language includes data types for generic 2-, 3-, and 4-component vectors of floating-point values, integers, or Booleans."
// 4 "The OpenGL Shading Language is type safe. There are no implicit conversions between types."
#version 110
void main()
{
    vec3 v = vec4(1.0);
    gl_Position = vec4(v, 1.0);
}
