// ARGS: --format json
uniform sampler2D base;
uniform vec3 key_color;
uniform float threshold;
varying vec2 uv;

void main() {
  vec4 texel = texture2D(base, uv);
  if (distance(texel.rgb, key_color) < threshold) discard;
  gl_FragData[0] = texel;
  gl_FragData[1] = vec4(gl_FragCoord.z);
}
