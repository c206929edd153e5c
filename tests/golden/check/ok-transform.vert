uniform mat4 m;
attribute vec4 p;
void main() { gl_Position = m * p; }
