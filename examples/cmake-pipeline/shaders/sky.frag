#version 110
// Sky dome: a gradient from the horizon colour to the zenith colour.
uniform vec3 horizon;
uniform vec3 zenith;
varying vec3 direction;

void main() {
  float height = clamp(normalize(direction).y, 0.0, 1.0);
  gl_FragColor = vec4(mix(horizon, zenith, height), 1.0);
}
