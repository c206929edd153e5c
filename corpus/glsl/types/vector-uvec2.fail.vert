// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.5 "The OpenGL Shading Language includes data types for generic 2-, 3-, and 4-component vectors of floating-point values, integers, or Booleans."
// 3.6 uvec2 is not a keyword of 1.10
#version 110
void main()
{
    uvec2 v;
    gl_Position = vec4(0.0);
}
