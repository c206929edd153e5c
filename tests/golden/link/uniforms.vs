uniform vec4 tint;
uniform mat4 bones[4];
uniform sampler2D map;

void main() {
  gl_Position = bones[0] * gl_Vertex + tint + texture2D(map, vec2(0.0));
}
