#version 110
// The vertex stage of a pair: gl_FrontColor leaves unclamped (transform feedback reads it
// as written); the fragment shader reads it clamped to [0, 1] (GL 2.0 2.14.6).
varying float k;
void main() {
  gl_Position = gl_Vertex;
  gl_FrontColor = vec4(2.0, -1.0, 0.5, 1.0);
  k = gl_Vertex.x * 3.0;
}
