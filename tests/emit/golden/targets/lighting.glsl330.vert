#version 330 core
// ARB vertex program translated to GLSL 3.30 core by arbiter.

layout(location = 0) in vec4 arb_vertex_position;  // vertex.position, location 0
layout(location = 2) in vec4 arb_vertex_normal;  // vertex.normal, location 2
out vec4 arb_bcolor0;
out vec4 arb_bcolor1;
out vec4 arb_color0;
out vec4 arb_color1;
uniform mat4 arb_matrix_modelview0_inverse;  // state.matrix.modelview[0].inverse
uniform mat4 arb_matrix_mvp0;  // state.matrix.mvp
uniform vec4 arb_state_light0_half;  // state.light[0].half
uniform vec4 arb_state_light0_position;  // state.light[0].position
uniform vec4 arb_state_lightmodel_back_scenecolor;  // state.lightmodel.back.scenecolor
uniform vec4 arb_state_lightmodel_front_scenecolor;  // state.lightmodel.front.scenecolor
uniform vec4 arb_state_lightprod0_back_ambient;  // state.lightprod[0].back.ambient
uniform vec4 arb_state_lightprod0_back_diffuse;  // state.lightprod[0].back.diffuse
uniform vec4 arb_state_lightprod0_back_specular;  // state.lightprod[0].back.specular
uniform vec4 arb_state_lightprod0_front_ambient;  // state.lightprod[0].front.ambient
uniform vec4 arb_state_lightprod0_front_diffuse;  // state.lightprod[0].front.diffuse
uniform vec4 arb_state_lightprod0_front_specular;  // state.lightprod[0].front.specular
uniform vec4 arb_state_material_back_shininess;  // state.material.back.shininess
uniform vec4 arb_state_material_front_shininess;  // state.material.front.shininess

// LIT (ARBvp 2.14.5.13): x and y clamped at 0, w to [-(128 - eps), 128 - eps] with
// 128 - eps = 127.99999 (the largest float below 128); z = x > 0 ? y^w : 0 with 0^0 = 1.
vec4 arb_lit(vec4 s) {
  float x = s.x < 0.0 ? 0.0 : s.x;
  float y = s.y < 0.0 ? 0.0 : s.y;
  float w = s.w < -127.99999 ? -127.99999 : (s.w > 127.99999 ? 127.99999 : s.w);
  float z = x > 0.0 ? (w == 0.0 ? 1.0 : pow(y, w)) : 0.0;
  return vec4(1.0, x, z, 1.0);
}

void main() {
  vec4 n = vec4(0.0);
  vec4 dots = vec4(0.0);
  vec4 lit = vec4(0.0);
  vec4 c = vec4(0.0);

  // DP4 result.position.x, mvp[0], iPos;
  gl_Position.x = dot(vec4(arb_matrix_mvp0[0][0], arb_matrix_mvp0[1][0], arb_matrix_mvp0[2][0], arb_matrix_mvp0[3][0]), arb_vertex_position);
  // DP4 result.position.y, mvp[1], iPos;
  gl_Position.y = dot(vec4(arb_matrix_mvp0[0][1], arb_matrix_mvp0[1][1], arb_matrix_mvp0[2][1], arb_matrix_mvp0[3][1]), arb_vertex_position);
  // DP4 result.position.z, mvp[2], iPos;
  gl_Position.z = dot(vec4(arb_matrix_mvp0[0][2], arb_matrix_mvp0[1][2], arb_matrix_mvp0[2][2], arb_matrix_mvp0[3][2]), arb_vertex_position);
  // DP4 result.position.w, mvp[3], iPos;
  gl_Position.w = dot(vec4(arb_matrix_mvp0[0][3], arb_matrix_mvp0[1][3], arb_matrix_mvp0[2][3], arb_matrix_mvp0[3][3]), arb_vertex_position);
  // DP3 n.x, mvit[0], iNrm;
  n.x = dot(arb_matrix_modelview0_inverse[0].xyz, arb_vertex_normal.xyz);
  // DP3 n.y, mvit[1], iNrm;
  n.y = dot(arb_matrix_modelview0_inverse[1].xyz, arb_vertex_normal.xyz);
  // DP3 n.z, mvit[2], iNrm;
  n.z = dot(arb_matrix_modelview0_inverse[2].xyz, arb_vertex_normal.xyz);
  // DP3 dots.x, n, L;
  dots.x = dot(n.xyz, arb_state_light0_position.xyz);
  // DP3 dots.y, n, H;
  dots.y = dot(n.xyz, arb_state_light0_half.xyz);
  // MOV dots.w, fShin.x;
  dots.w = arb_state_material_front_shininess.x;
  // LIT lit, dots;
  lit = arb_lit(dots);
  // ADD c, fScene, fAmb;
  c = arb_state_lightmodel_front_scenecolor + arb_state_lightprod0_front_ambient;
  // MAD c, lit.y, fDif, c;
  c = lit.yyyy * arb_state_lightprod0_front_diffuse + c;
  // MOV result.color.front.primary.xyz, c;
  arb_color0.xyz = c.xyz;
  // MOV result.color.front.primary.w, fDif.w;
  arb_color0.w = arb_state_lightprod0_front_diffuse.w;
  // MUL result.color.front.secondary, lit.z, fSpe;
  arb_color1 = lit.zzzz * arb_state_lightprod0_front_specular;
  // DP3 dots.x, -n, L;
  dots.x = dot(-n.xyz, arb_state_light0_position.xyz);
  // DP3 dots.y, -n, H;
  dots.y = dot(-n.xyz, arb_state_light0_half.xyz);
  // MOV dots.w, bShin.x;
  dots.w = arb_state_material_back_shininess.x;
  // LIT lit, dots;
  lit = arb_lit(dots);
  // ADD c, bScene, bAmb;
  c = arb_state_lightmodel_back_scenecolor + arb_state_lightprod0_back_ambient;
  // MAD c, lit.y, bDif, c;
  c = lit.yyyy * arb_state_lightprod0_back_diffuse + c;
  // MOV result.color.back.primary.xyz, c;
  arb_bcolor0.xyz = c.xyz;
  // MOV result.color.back.primary.w, bDif.w;
  arb_bcolor0.w = arb_state_lightprod0_back_diffuse.w;
  // MUL result.color.back.secondary, lit.z, bSpe;
  arb_bcolor1 = lit.zzzz * arb_state_lightprod0_back_specular;

  arb_bcolor0 = clamp(arb_bcolor0, 0.0, 1.0);  // GL clamps the vertex colours
  arb_bcolor1 = clamp(arb_bcolor1, 0.0, 1.0);  // GL clamps the vertex colours
  arb_color0 = clamp(arb_color0, 0.0, 1.0);  // GL clamps the vertex colours
  arb_color1 = clamp(arb_color1, 0.0, 1.0);  // GL clamps the vertex colours
}
