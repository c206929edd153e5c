// Within Mesa's limits, past the GL 2.0 minimums: 36 varying floats, a vertex texture,
// 3 texture units for the program.
varying vec4 layers[8];
varying vec4 extra;
uniform sampler2D displacement;

void main() {
  for (int i = 0; i < 8; ++i) layers[i] = gl_MultiTexCoord0 * float(i);
  extra = texture2D(displacement, gl_MultiTexCoord0.xy);
  gl_Position = ftransform();
}
