#version 450
layout(push_constant) uniform Local { vec2 local[2]; } local;
layout(location = 0) in vec4 p;
void main() { gl_Position = p + local.local[1].xyxy; }
