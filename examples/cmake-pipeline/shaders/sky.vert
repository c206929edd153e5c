#version 110
// Sky dome: direction of the vertex for the fragment shader.
varying vec3 direction;

void main() {
  direction = gl_Vertex.xyz;
  gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
