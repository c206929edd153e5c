// A valid vertex shader with a warning: a name with "__" (reserved, GLSL 1.10 3.6).
float my__scale = 1.0;
void main() { gl_Position = ftransform() * my__scale; }
