// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.7 "Identifiers starting with \"gl_\" are reserved for use by OpenGL, and may not be declared in a shader as either a variable or a function." (only the exact prefix gl_ is reserved)
#version 110
float gl = 1.0;
float glx = 1.0;
float Gl_x = 1.0;
float GL_x = 1.0;
float _gl_x = 1.0;
float agl_x = 1.0;
float my_gl_x = 1.0;
void main()
{
    gl_Position = vec4(gl * glx * Gl_x * GL_x * _gl_x * agl_x * my_gl_x);
}
