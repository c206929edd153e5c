#version 110
// ARB vertex program translated to GLSL 1.10 by arbiter.

// LIT (ARBvp 2.14.5.13): x and y clamped at 0, w to [-(128 - eps), 128 - eps] with
// 128 - eps = 127.99999 (the largest float below 128); z = x > 0 ? y^w : 0 with 0^0 = 1.
vec4 arb_lit(vec4 s) {
  float x = s.x < 0.0 ? 0.0 : s.x;
  float y = s.y < 0.0 ? 0.0 : s.y;
  float w = s.w < -127.99999 ? -127.99999 : (s.w > 127.99999 ? 127.99999 : s.w);
  float z = x > 0.0 ? (w == 0.0 ? 1.0 : pow(y, w)) : 0.0;
  return vec4(1.0, x, z, 1.0);
}

// EXP (ARBvp 2.14.5.9): (2^floor(t), t - floor(t), 2^t, 1).
vec4 arb_exp(float t) {
  float f = floor(t);
  return vec4(exp2(f), t - f, exp2(t), 1.0);
}

// LOG (ARBvp 2.14.5.14): (floor(log2|t|), |t| / 2^floor(log2|t|), log2|t|, 1). The
// exponent is corrected where log2 rounds across an integer: the mantissa is in [1, 2).
vec4 arb_log(float t) {
  float a = abs(t);
  float e = floor(log2(a));
  float m = a / exp2(e);
  if (m >= 2.0) {
    e += 1.0;
    m *= 0.5;
  }
  if (m < 1.0) {
    e -= 1.0;
    m *= 2.0;
  }
  return vec4(e, m, log2(a), 1.0);
}

void main() {
  vec4 t = vec4(0.0);
  vec4 u = vec4(0.0);
  vec4 r = vec4(0.0);

  // DP4 result.position.x, mvp[0], iPos;
  gl_Position.x = dot(gl_ModelViewProjectionMatrixTranspose[0], gl_Vertex);
  // DP4 result.position.y, mvp[1], iPos;
  gl_Position.y = dot(gl_ModelViewProjectionMatrixTranspose[1], gl_Vertex);
  // DP4 result.position.z, mvp[2], iPos;
  gl_Position.z = dot(gl_ModelViewProjectionMatrixTranspose[2], gl_Vertex);
  // DP4 result.position.w, mvp[3], iPos;
  gl_Position.w = dot(gl_ModelViewProjectionMatrixTranspose[3], gl_Vertex);
  // SWZ t, iNrm, -x, 0, 1, -w;
  t = vec4(-gl_Normal.x, 0.0, 1.0, -1.0);
  // SWZ u.xz, iPos, y, -1, -0, z;
  u.xz = vec2(gl_Vertex.y, -0.0);
  // LIT r, t;
  r = arb_lit(t);
  // EXP r.xy, u.x;
  r.xy = arb_exp(u.x).xy;
  // LOG u, -t.y;
  u = arb_log(-t.y);
  // DST r.yzw, t, u;
  r.yzw = vec3(t.y * u.y, t.z, u.w);
  // XPD t.xyz, iNrm, k;
  t.xyz = cross(gl_Normal, vec3(0.5, -2.0, 3.0));
  // RSQ t.w, k.y;
  t.w = inversesqrt(abs(-2.0));
  // MUL result.texcoord[0], r, t;
  gl_TexCoord[0] = r * t;
  // MAD result.texcoord[1], u.zxyw, -k, -iNrm;
  gl_TexCoord[1] = u.zxyw * vec4(-0.5, 2.0, -3.0, -1.0) + -vec4(gl_Normal, 1.0);
  // MOV result.fogcoord, u.z;
  gl_FogFragCoord = u.z;
  // MOV result.pointsize.x, r.y;
  gl_PointSize = r.y;
}
