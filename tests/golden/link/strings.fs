varying vec3 uv;
uniform vec4 tint;
void main() { gl_FragColor = tint * uv.x; }
