#version 120
// ARB vertex program translated to GLSL 1.20 by arbiter.

// LIT (ARBvp 2.14.5.13): x and y clamped at 0, w to [-(128 - eps), 128 - eps] with
// 128 - eps = 127.99999 (the largest float below 128); z = x > 0 ? y^w : 0 with 0^0 = 1.
vec4 arb_lit(vec4 s) {
  float x = s.x < 0.0 ? 0.0 : s.x;
  float y = s.y < 0.0 ? 0.0 : s.y;
  float w = s.w < -127.99999 ? -127.99999 : (s.w > 127.99999 ? 127.99999 : s.w);
  float z = x > 0.0 ? (w == 0.0 ? 1.0 : pow(y, w)) : 0.0;
  return vec4(1.0, x, z, 1.0);
}

// state.light[n].half (ARBvp table X.3.3): (normalize(P + (0, 0, 1)), 1) with P the unit
// vector from the eye to the light (xyz / w for a local light).
vec4 arb_half(vec4 p) {
  vec3 d = p.w != 0.0 ? p.xyz / p.w : p.xyz;
  return vec4(normalize(normalize(d) + vec3(0.0, 0.0, 1.0)), 1.0);
}

void main() {
  vec4 n = vec4(0.0);
  vec4 dots = vec4(0.0);
  vec4 lit = vec4(0.0);
  vec4 c = vec4(0.0);

  // DP4 result.position.x, mvp[0], iPos;
  gl_Position.x = dot(gl_ModelViewProjectionMatrixTranspose[0], gl_Vertex);
  // DP4 result.position.y, mvp[1], iPos;
  gl_Position.y = dot(gl_ModelViewProjectionMatrixTranspose[1], gl_Vertex);
  // DP4 result.position.z, mvp[2], iPos;
  gl_Position.z = dot(gl_ModelViewProjectionMatrixTranspose[2], gl_Vertex);
  // DP4 result.position.w, mvp[3], iPos;
  gl_Position.w = dot(gl_ModelViewProjectionMatrixTranspose[3], gl_Vertex);
  // DP3 n.x, mvit[0], iNrm;
  n.x = dot(gl_ModelViewMatrixInverse[0].xyz, gl_Normal);
  // DP3 n.y, mvit[1], iNrm;
  n.y = dot(gl_ModelViewMatrixInverse[1].xyz, gl_Normal);
  // DP3 n.z, mvit[2], iNrm;
  n.z = dot(gl_ModelViewMatrixInverse[2].xyz, gl_Normal);
  // DP3 dots.x, n, L;
  dots.x = dot(n.xyz, gl_LightSource[0].position.xyz);
  // DP3 dots.y, n, H;
  dots.y = dot(n.xyz, arb_half(gl_LightSource[0].position).xyz);
  // MOV dots.w, fShin.x;
  dots.w = gl_FrontMaterial.shininess;
  // LIT lit, dots;
  lit = arb_lit(dots);
  // ADD c, fScene, fAmb;
  c = vec4(gl_FrontLightModelProduct.sceneColor.rgb, gl_FrontMaterial.diffuse.a) + vec4(gl_FrontLightProduct[0].ambient.rgb, gl_FrontMaterial.ambient.a);
  // MAD c, lit.y, fDif, c;
  c = lit.yyyy * vec4(gl_FrontLightProduct[0].diffuse.rgb, gl_FrontMaterial.diffuse.a) + c;
  // MOV result.color.front.primary.xyz, c;
  gl_FrontColor.xyz = c.xyz;
  // MOV result.color.front.primary.w, fDif.w;
  gl_FrontColor.w = gl_FrontMaterial.diffuse.a;
  // MUL result.color.front.secondary, lit.z, fSpe;
  gl_FrontSecondaryColor = lit.zzzz * vec4(gl_FrontLightProduct[0].specular.rgb, gl_FrontMaterial.specular.a);
  // DP3 dots.x, -n, L;
  dots.x = dot(-n.xyz, gl_LightSource[0].position.xyz);
  // DP3 dots.y, -n, H;
  dots.y = dot(-n.xyz, arb_half(gl_LightSource[0].position).xyz);
  // MOV dots.w, bShin.x;
  dots.w = gl_BackMaterial.shininess;
  // LIT lit, dots;
  lit = arb_lit(dots);
  // ADD c, bScene, bAmb;
  c = vec4(gl_BackLightModelProduct.sceneColor.rgb, gl_BackMaterial.diffuse.a) + vec4(gl_BackLightProduct[0].ambient.rgb, gl_BackMaterial.ambient.a);
  // MAD c, lit.y, bDif, c;
  c = lit.yyyy * vec4(gl_BackLightProduct[0].diffuse.rgb, gl_BackMaterial.diffuse.a) + c;
  // MOV result.color.back.primary.xyz, c;
  gl_BackColor.xyz = c.xyz;
  // MOV result.color.back.primary.w, bDif.w;
  gl_BackColor.w = gl_BackMaterial.diffuse.a;
  // MUL result.color.back.secondary, lit.z, bSpe;
  gl_BackSecondaryColor = lit.zzzz * vec4(gl_BackLightProduct[0].specular.rgb, gl_BackMaterial.specular.a);
}
