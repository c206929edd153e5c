varying vec3 normal;
varying vec2 uv;
varying vec3 tangent;

void main() {
  gl_FragColor = vec4(normal + tangent, uv.x);
}
