void main() {
  vec4 c = gl_Color;
}
