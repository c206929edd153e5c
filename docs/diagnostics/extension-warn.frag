// #extension ... : warn asks the compiler to warn at every use of the extension (3.3).
#extension GL_ARB_shader_texture_lod : warn
uniform sampler2D s;
void main() { gl_FragColor = texture2DLod(s, vec2(0.5), 1.0); }
