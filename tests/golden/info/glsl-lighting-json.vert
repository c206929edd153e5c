// ARGS: --format json
attribute mat4 bone;
uniform float scale;
uniform sampler2D height_map;
varying float height;
varying vec4 unwritten;

void main() {
  height = texture2D(height_map, gl_MultiTexCoord0.xy).r * scale;
  gl_Position = gl_ModelViewProjectionMatrix * (bone * gl_Vertex);
}
