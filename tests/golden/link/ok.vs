// A vertex shader that feeds every varying ok.fs reads.
uniform mat4 mvp;
uniform vec4 tint;
uniform sampler2D detail;
attribute vec4 position;
varying vec2 uv;
varying vec3 normal;
varying float unused_by_fragment;

void main() {
  uv = gl_MultiTexCoord0.xy;
  normal = gl_NormalMatrix * gl_Normal;
  unused_by_fragment = 1.0;
  gl_FrontColor = gl_Color * tint;
  gl_TexCoord[0] = gl_MultiTexCoord0;
  gl_Position = mvp * position;
}
