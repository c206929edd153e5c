#version 110
varying vec3 t;
void main() {
  gl_Position = gl_Vertex;
  t = normalise(gl_Normal);
}
