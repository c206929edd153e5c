// Reads varyings ok.vs writes, built-in varyings, and a uniform of ok.vs' type.
uniform vec4 tint;
uniform sampler2D detail;
varying vec2 uv;
varying vec3 normal;
varying vec4 declared_not_read;

void main() {
  vec4 c = texture2D(detail, uv) * gl_Color * gl_TexCoord[0];
  gl_FragColor = c * tint * max(normal.z, 0.0);
}
