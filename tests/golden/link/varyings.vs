// Declares 'normal' without writing it, 'uv' as a vec3, and no 'tangent'.
varying vec3 normal;
varying vec3 uv;

void main() {
  uv = vec3(gl_MultiTexCoord0);
  gl_Position = ftransform();
}
