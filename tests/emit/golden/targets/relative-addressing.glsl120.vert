#version 120
// ARB vertex program translated to GLSL 1.20 by arbiter.

attribute vec4 arb_attrib6;  // vertex.attrib[6], location 6
uniform vec4 arb_vp_env[8];  // program.env[0..7]
vec4 palette[8];  // PARAM palette, read with relative addressing

// palette[A0.x + k]: a read outside palette[0..7] gives vec4(0.0) (undefined in ARB).
vec4 arb_read_palette(int arb_i) {
  if (arb_i < 0 || arb_i > 7) return vec4(0.0);
  return palette[arb_i];
}

void main() {
  int A0 = 0;
  palette[0] = arb_vp_env[0];
  palette[1] = arb_vp_env[1];
  palette[2] = arb_vp_env[2];
  palette[3] = arb_vp_env[3];
  palette[4] = arb_vp_env[4];
  palette[5] = arb_vp_env[5];
  palette[6] = arb_vp_env[6];
  palette[7] = arb_vp_env[7];

  // DP4 result.position.x, mvp[0], iPos;
  gl_Position.x = dot(gl_ModelViewProjectionMatrixTranspose[0], gl_Vertex);
  // DP4 result.position.y, mvp[1], iPos;
  gl_Position.y = dot(gl_ModelViewProjectionMatrixTranspose[1], gl_Vertex);
  // DP4 result.position.z, mvp[2], iPos;
  gl_Position.z = dot(gl_ModelViewProjectionMatrixTranspose[2], gl_Vertex);
  // DP4 result.position.w, mvp[3], iPos;
  gl_Position.w = dot(gl_ModelViewProjectionMatrixTranspose[3], gl_Vertex);
  // ARL A0.x, iIdx.x;
  A0 = int(floor(arb_attrib6.x));
  // MOV result.color, palette[A0.x];
  gl_FrontColor = arb_read_palette(A0);
  // MOV result.color.secondary, palette[A0.x+4];
  gl_FrontSecondaryColor = arb_read_palette(A0 + 4);
}
