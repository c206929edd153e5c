#version 100
// ARB vertex program translated to GLSL ES 1.00 by arbiter.

precision highp float;
precision highp int;

attribute vec4 arb_vertex_position;  // vertex.position, location 0
attribute vec4 arb_vertex_normal;  // vertex.normal, location 2
attribute vec4 arb_vertex_texcoord0;  // vertex.texcoord[0], location 8
varying vec4 arb_color0;
varying vec4 arb_texcoord0;
varying vec4 arb_user_clip0;
varying vec2 arb_user_clip1;
uniform vec4 arb_clip0_enabled;  // clip[0].enabled
uniform vec4 arb_clip1_enabled;  // clip[1].enabled
uniform vec4 arb_clip2_enabled;  // clip[2].enabled
uniform vec4 arb_clip3_enabled;  // clip[3].enabled
uniform vec4 arb_clip4_enabled;  // clip[4].enabled
uniform vec4 arb_clip5_enabled;  // clip[5].enabled
uniform mat4 arb_matrix_modelview0;  // state.matrix.modelview[0]
uniform mat4 arb_matrix_modelview0_inverse;  // state.matrix.modelview[0].inverse
uniform mat4 arb_matrix_mvp0;  // state.matrix.mvp
uniform vec4 arb_state_clip0_plane;  // state.clip[0].plane
uniform vec4 arb_state_clip1_plane;  // state.clip[1].plane
uniform vec4 arb_state_clip2_plane;  // state.clip[2].plane
uniform vec4 arb_state_clip3_plane;  // state.clip[3].plane
uniform vec4 arb_state_clip4_plane;  // state.clip[4].plane
uniform vec4 arb_state_clip5_plane;  // state.clip[5].plane
uniform vec4 arb_state_light0_position;  // state.light[0].position
uniform vec4 arb_state_lightprod0_front_ambient;  // state.lightprod[0].front.ambient
uniform vec4 arb_state_lightprod0_front_diffuse;  // state.lightprod[0].front.diffuse

void main() {
  vec4 n = vec4(0.0);
  vec4 d = vec4(0.0);
  gl_Position = arb_matrix_mvp0 * arb_vertex_position;  // OPTION ARB_position_invariant
  vec4 arb_eye_position = arb_matrix_modelview0 * arb_vertex_position;
  arb_user_clip0 = vec4((arb_clip0_enabled.x != 0.0 ? dot(arb_state_clip0_plane, arb_eye_position) : 1.0), (arb_clip1_enabled.x != 0.0 ? dot(arb_state_clip1_plane, arb_eye_position) : 1.0), (arb_clip2_enabled.x != 0.0 ? dot(arb_state_clip2_plane, arb_eye_position) : 1.0), (arb_clip3_enabled.x != 0.0 ? dot(arb_state_clip3_plane, arb_eye_position) : 1.0));
  arb_user_clip1 = vec2((arb_clip4_enabled.x != 0.0 ? dot(arb_state_clip4_plane, arb_eye_position) : 1.0), (arb_clip5_enabled.x != 0.0 ? dot(arb_state_clip5_plane, arb_eye_position) : 1.0));

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
