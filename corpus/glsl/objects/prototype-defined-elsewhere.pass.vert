// [config]
// expect_result: pass
// glsl_version: 1.20
// [end config]
// 6.1: "a function may be declared ... with a prototype ... and defined ... in another shader" (glCompileShader accepts the prototype alone)
#version 120
vec4 skin(vec4 position);
void main()
{
    gl_Position = gl_ModelViewProjectionMatrix * skin(gl_Vertex);
}
