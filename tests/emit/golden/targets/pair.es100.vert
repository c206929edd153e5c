#version 100
// ARB vertex program translated to GLSL ES 1.00 by arbiter.

precision highp float;
precision highp int;

attribute vec4 arb_vertex_position;  // vertex.position, location 0
attribute vec4 arb_vertex_color;  // vertex.color.primary, location 3
attribute vec4 arb_vertex_attrib7;  // vertex.attrib[7], location 7
attribute vec4 arb_vertex_texcoord0;  // vertex.texcoord[0], location 8
varying vec4 arb_color0;
varying float arb_fogcoord;
varying vec4 arb_texcoord0;
varying vec4 arb_texcoord2;
uniform mat4 arb_matrix_mvp0;  // state.matrix.mvp
uniform mat4 arb_matrix_program1;  // state.matrix.program[1]

void main() {
  vec4 p = vec4(0.0);

  // DP4 p.x, mvp[0], iPos;
  p.x = dot(vec4(arb_matrix_mvp0[0][0], arb_matrix_mvp0[1][0], arb_matrix_mvp0[2][0], arb_matrix_mvp0[3][0]), arb_vertex_position);
  // DP4 p.y, mvp[1], iPos;
  p.y = dot(vec4(arb_matrix_mvp0[0][1], arb_matrix_mvp0[1][1], arb_matrix_mvp0[2][1], arb_matrix_mvp0[3][1]), arb_vertex_position);
  // DP4 p.z, mvp[2], iPos;
  p.z = dot(vec4(arb_matrix_mvp0[0][2], arb_matrix_mvp0[1][2], arb_matrix_mvp0[2][2], arb_matrix_mvp0[3][2]), arb_vertex_position);
  // DP4 p.w, mvp[3], iPos;
  p.w = dot(vec4(arb_matrix_mvp0[0][3], arb_matrix_mvp0[1][3], arb_matrix_mvp0[2][3], arb_matrix_mvp0[3][3]), arb_vertex_position);
  // MOV result.position, p;
  gl_Position = p;
  // MOV result.texcoord[0], vertex.texcoord[0];
  arb_texcoord0 = arb_vertex_texcoord0;
  // MUL result.texcoord[2], vertex.attrib[7], mv2;
  arb_texcoord2 = arb_vertex_attrib7 * vec4(arb_matrix_program1[0][2], arb_matrix_program1[1][2], arb_matrix_program1[2][2], arb_matrix_program1[3][2]);
  // MOV result.fogcoord.x, p.z;
  arb_fogcoord = p.z;
  // MOV result.color, vertex.color;
  arb_color0 = arb_vertex_color;

  arb_color0 = clamp(arb_color0, 0.0, 1.0);  // GL clamps the vertex colours
}
