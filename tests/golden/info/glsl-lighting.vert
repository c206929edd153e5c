// Per-vertex lighting with one light: attributes, uniforms, varyings and built-in state.
attribute vec3 tangent;
attribute float unused_weight;
uniform mat3 normal_basis;
uniform vec4 tints[2];
varying vec3 eye_normal;
varying vec2 uv;

void main() {
  eye_normal = normalize(gl_NormalMatrix * gl_Normal + normal_basis * tangent);
  float lambert = max(dot(eye_normal, gl_LightSource[0].position.xyz), 0.0);
  gl_FrontColor = gl_LightSource[0].diffuse * gl_FrontMaterial.diffuse * lambert + tints[1];
  uv = gl_MultiTexCoord0.xy;
  gl_TexCoord[0] = gl_TextureMatrix[0] * gl_MultiTexCoord0;
  gl_Position = ftransform();
}
