// Writes every varying ok.fs reads, but never gl_Position.
varying vec2 uv;
varying vec3 normal;
void main() {
  uv = gl_MultiTexCoord0.xy;
  normal = gl_Normal;
  gl_FrontColor = gl_Color;
  gl_TexCoord[0] = gl_MultiTexCoord0;
}
