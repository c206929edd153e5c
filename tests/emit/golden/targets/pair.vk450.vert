#version 450
// ARB vertex program translated to GLSL 4.50 (Vulkan) by arbiter.

layout(location = 0) in vec4 arb_vertex_position;  // vertex.position, location 0
layout(location = 3) in vec4 arb_vertex_color;  // vertex.color.primary, location 3
layout(location = 7) in vec4 arb_vertex_attrib7;  // vertex.attrib[7], location 7
layout(location = 8) in vec4 arb_vertex_texcoord0;  // vertex.texcoord[0], location 8
layout(location = 0) out vec4 arb_color0;
layout(location = 4) out float arb_fogcoord;
layout(location = 5) out vec4 arb_texcoord0;
layout(location = 7) out vec4 arb_texcoord2;
layout(std140, set = 0, binding = 0) uniform ArbVertexUniforms {
  mat4 arb_matrix_mvp0;  // state.matrix.mvp  offset 0
  mat4 arb_matrix_program1;  // state.matrix.program[1]  offset 64
};

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
