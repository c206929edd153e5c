#version 110
// 'unused' is declared but no output depends on it: Mesa removes it. A value for it is a
// note; a wrong number of values is still an error (judged from the declaration).
uniform vec3 unused;
void main() { gl_Position = gl_Vertex; }
