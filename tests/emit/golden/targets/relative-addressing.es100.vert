#version 100
// ARB vertex program translated to GLSL ES 1.00 by arbiter.

precision highp float;
precision highp int;

attribute vec4 arb_vertex_position;  // vertex.position, location 0
attribute vec4 arb_vertex_attrib6;  // vertex.attrib[6], location 6
varying vec4 arb_color0;
varying vec4 arb_color1;
uniform vec4 arb_vp_env[8];  // program.env[0..7]
uniform mat4 arb_matrix_mvp0;  // state.matrix.mvp
vec4 palette[8];  // PARAM palette, read with relative addressing

// palette[A0.x + k]: program.env[0 + A0.x + k]; a read outside palette[0..7] gives
// vec4(0.0) (undefined in ARB).
vec4 arb_read_palette(int arb_i) {
  if (arb_i < 0 || arb_i > 7) return vec4(0.0);
  return arb_vp_env[0 + arb_i];
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
  gl_Position.x = dot(vec4(arb_matrix_mvp0[0][0], arb_matrix_mvp0[1][0], arb_matrix_mvp0[2][0], arb_matrix_mvp0[3][0]), arb_vertex_position);
  // DP4 result.position.y, mvp[1], iPos;
  gl_Position.y = dot(vec4(arb_matrix_mvp0[0][1], arb_matrix_mvp0[1][1], arb_matrix_mvp0[2][1], arb_matrix_mvp0[3][1]), arb_vertex_position);
  // DP4 result.position.z, mvp[2], iPos;
  gl_Position.z = dot(vec4(arb_matrix_mvp0[0][2], arb_matrix_mvp0[1][2], arb_matrix_mvp0[2][2], arb_matrix_mvp0[3][2]), arb_vertex_position);
  // DP4 result.position.w, mvp[3], iPos;
  gl_Position.w = dot(vec4(arb_matrix_mvp0[0][3], arb_matrix_mvp0[1][3], arb_matrix_mvp0[2][3], arb_matrix_mvp0[3][3]), arb_vertex_position);
  // ARL A0.x, iIdx.x;
  A0 = int(floor(arb_vertex_attrib6.x));
  // MOV result.color, palette[A0.x];
  arb_color0 = arb_read_palette(A0);
  // MOV result.color.secondary, palette[A0.x+4];
  arb_color1 = arb_read_palette(A0 + 4);

  arb_color0 = clamp(arb_color0, 0.0, 1.0);  // GL clamps the vertex colours
  arb_color1 = clamp(arb_color1, 0.0, 1.0);  // GL clamps the vertex colours
}
