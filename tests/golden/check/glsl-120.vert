#version 120
// 1.20: implicit conversions, array constructors, non-square matrices; __ names warn.
uniform mat2x3 m;
varying vec3 v;
const float weights[3] = float[3](0.25, 0.5, 0.25);
float my__scale = 2;
void main() {
  v = (m * vec2(1, 0)) * weights[weights.length() - 1] * my__scale;
  gl_Position = vec4(v, 1);
}
