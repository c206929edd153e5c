#version 110
// lightDir and tex are not given: each is a note, and reads zero / texture unit 0.
uniform vec3 lightDir;
uniform sampler2D tex;
varying vec4 c;
void main() {
  gl_Position = gl_Vertex;
  c = vec4(lightDir, 1.0) + texture2DLod(tex, vec2(0.5), 0.0);
}
