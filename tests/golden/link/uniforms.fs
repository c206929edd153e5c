uniform vec3 tint;
uniform mat4 bones[2];
uniform samplerCube map;

void main() {
  gl_FragColor = textureCube(map, tint) * bones[1][0];
}
