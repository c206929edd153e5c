// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.5 "The OpenGL Shading Language includes data types for generic 2-, 3-, and 4-component vectors of floating-point values, integers, or Booleans."
void main()
{
    vec1 v;
    gl_FragColor = vec4(0.0);
}
