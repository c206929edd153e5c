// 68 uniform components (the minimum is 64) and two samplers.
uniform vec4 palette[16];
uniform vec4 fog;
uniform sampler2D base;
uniform sampler2D detail;
varying vec4 layers[8];

void main() {
  vec4 c = fog;
  for (int i = 0; i < 16; ++i) c += palette[i];
  gl_FragColor = c * layers[3] * texture2D(base, vec2(0.5)) * texture2D(detail, vec2(0.5));
}
