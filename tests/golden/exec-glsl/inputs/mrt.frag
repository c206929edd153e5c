#version 110
// Two render targets, a depth and a discard: per vector, from the vectors file.
varying vec3 t;
void main() {
  if (gl_TexCoord[0].x < 0.0) discard;
  gl_FragData[0] = gl_Color;
  gl_FragData[1] = vec4(t, gl_FragCoord.z);
  gl_FragDepth = gl_FragCoord.z * 0.5;
}
