#version 450
// ARB vertex program translated to GLSL 4.50 (Vulkan) by arbiter.

layout(location = 0) in vec4 arb_vertex_position;  // vertex.position, location 0
layout(location = 2) in vec4 arb_vertex_normal;  // vertex.normal, location 2
layout(location = 8) in vec4 arb_vertex_texcoord0;  // vertex.texcoord[0], location 8
layout(location = 0) out vec4 arb_color0;
layout(location = 5) out vec4 arb_texcoord0;
layout(std140, set = 0, binding = 0) uniform ArbVertexUniforms {
  vec4 arb_clip0_enabled;  // clip[0].enabled  offset 0
  vec4 arb_clip1_enabled;  // clip[1].enabled  offset 16
  vec4 arb_clip2_enabled;  // clip[2].enabled  offset 32
  vec4 arb_clip3_enabled;  // clip[3].enabled  offset 48
  vec4 arb_clip4_enabled;  // clip[4].enabled  offset 64
  vec4 arb_clip5_enabled;  // clip[5].enabled  offset 80
  mat4 arb_matrix_modelview0;  // state.matrix.modelview[0]  offset 96
  mat4 arb_matrix_modelview0_inverse;  // state.matrix.modelview[0].inverse  offset 160
  mat4 arb_matrix_mvp0;  // state.matrix.mvp  offset 224
  vec4 arb_state_clip0_plane;  // state.clip[0].plane  offset 288
  vec4 arb_state_clip1_plane;  // state.clip[1].plane  offset 304
  vec4 arb_state_clip2_plane;  // state.clip[2].plane  offset 320
  vec4 arb_state_clip3_plane;  // state.clip[3].plane  offset 336
  vec4 arb_state_clip4_plane;  // state.clip[4].plane  offset 352
  vec4 arb_state_clip5_plane;  // state.clip[5].plane  offset 368
  vec4 arb_state_light0_position;  // state.light[0].position  offset 384
  vec4 arb_state_lightprod0_front_ambient;  // state.lightprod[0].front.ambient  offset 400
  vec4 arb_state_lightprod0_front_diffuse;  // state.lightprod[0].front.diffuse  offset 416
};

void main() {
  vec4 n = vec4(0.0);
  vec4 d = vec4(0.0);
  gl_Position = arb_matrix_mvp0 * arb_vertex_position;  // OPTION ARB_position_invariant
  vec4 arb_eye_position = arb_matrix_modelview0 * arb_vertex_position;
  gl_ClipDistance[0] = (arb_clip0_enabled.x != 0.0 ? dot(arb_state_clip0_plane, arb_eye_position) : 0.0);
  gl_ClipDistance[1] = (arb_clip1_enabled.x != 0.0 ? dot(arb_state_clip1_plane, arb_eye_position) : 0.0);
  gl_ClipDistance[2] = (arb_clip2_enabled.x != 0.0 ? dot(arb_state_clip2_plane, arb_eye_position) : 0.0);
  gl_ClipDistance[3] = (arb_clip3_enabled.x != 0.0 ? dot(arb_state_clip3_plane, arb_eye_position) : 0.0);
  gl_ClipDistance[4] = (arb_clip4_enabled.x != 0.0 ? dot(arb_state_clip4_plane, arb_eye_position) : 0.0);
  gl_ClipDistance[5] = (arb_clip5_enabled.x != 0.0 ? dot(arb_state_clip5_plane, arb_eye_position) : 0.0);

  // DP3 n.x, mvit[0], iNrm;
  n.x = dot(arb_matrix_modelview0_inverse[0].xyz, arb_vertex_normal.xyz);
  // DP3 n.y, mvit[1], iNrm;
  n.y = dot(arb_matrix_modelview0_inverse[1].xyz, arb_vertex_normal.xyz);
  // DP3 n.z, mvit[2], iNrm;
  n.z = dot(arb_matrix_modelview0_inverse[2].xyz, arb_vertex_normal.xyz);
  // DP3 d.x, n, L;
  d.x = dot(n.xyz, arb_state_light0_position.xyz);
  // MAX d.x, d.x, 0.0;
  d.x = max(d.x, 0.0);
  // MAD result.color, dif, d.x, amb;
  arb_color0 = arb_state_lightprod0_front_diffuse * d.xxxx + arb_state_lightprod0_front_ambient;
  // MOV result.texcoord[0], vertex.texcoord[0];
  arb_texcoord0 = arb_vertex_texcoord0;

  arb_color0 = clamp(arb_color0, 0.0, 1.0);  // GL clamps the vertex colours
}
