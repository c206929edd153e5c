// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.6 "the OpenGL Shading Language defines support for 2x2, 3x3, and 4x4 matrices of floating point numbers."
// 4.1.6 "mat2 mat2D; mat3 optMatrix; mat4 view, projection;"
#version 110
void main()
{
    mat2 mat2D;
    mat3 optMatrix;
    mat4 view, projection;
    mat2D = mat2(1.0);
    optMatrix = mat3(1.0);
    view = mat4(1.0);
    projection = mat4(2.0);
    gl_Position = projection * view * vec4(optMatrix[0], mat2D[1][1]);
}
