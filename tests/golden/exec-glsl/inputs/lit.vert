#version 110
// Diffuse lighting of one light in eye space, with its inputs spelled in GLSL.
// gl_Position = P * MV * gl_Vertex (GLSL 1.10 7.5); the --state matrices are row-major.
attribute vec3 tangent;
uniform vec3 lightDir;
struct Material { vec3 color; float shininess; };
uniform Material material;
uniform float weights[3];
varying vec3 t;
varying float diffuse;
void main() {
  gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
  t = normalize(tangent);
  // clamp(dot(t, L), 0, 1), weighted, plus pow(2, shininess)
  diffuse = clamp(dot(t, lightDir), 0.0, 1.0) * weights[2] + pow(2.0, material.shininess);
  gl_FrontColor = vec4(mix(material.color, vec3(1.0), 0.5), 1.0);
  gl_TexCoord[1] = gl_MultiTexCoord0 * 2.0;
}
