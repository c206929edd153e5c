varying vec4 v;
void main() {
  float x = 1;
  gl_Position = foo + vec4(1.0f);
  v = vec4(1.0) ;
}
