// [config]
// expect_result: fail
// glsl_version: 1.20
// [end config]
// 1.20 5.10: a mat2x3 (2 columns, 3 rows) times a vector needs a vec2: "the number of columns of the left operand [must equal] the number of rows of the right"
#version 120
uniform mat2x3 m;
void main()
{
    gl_Position = vec4(m * vec3(1.0), 1.0);
}
