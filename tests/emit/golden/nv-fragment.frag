#version 110
#extension GL_ARB_shader_texture_lod : require
// ARB fragment program translated to GLSL 1.10 by arbiter.

uniform sampler2D arb_texture0;  // texture[0], 2D

// ARR (NV_vertex_program2_option 2.14.5.29): the nearest integer, a tie to the even one.
float arb_round_even(float x) {
  float f = floor(x);
  float d = x - f;
  return d > 0.5 || (d == 0.5 && fract(f * 0.5) != 0.0) ? f + 1.0 : f;
}
vec2 arb_round_even(vec2 v) { return vec2(arb_round_even(v.x), arb_round_even(v.y)); }
vec3 arb_round_even(vec3 v) { return vec3(arb_round_even(v.x), arb_round_even(v.y), arb_round_even(v.z)); }
vec4 arb_round_even(vec4 v) { return vec4(arb_round_even(v.x), arb_round_even(v.y), arb_round_even(v.z), arb_round_even(v.w)); }

// fp16 (NV_fragment_program 3.11.4.1-2): the nearest half float, ties to even, with
// fp16 denormals (steps of 2^-24 below 2^-14); |x| >= 65520 rounds to infinity;
// NaN, infinities and zeros are unchanged. Exact: every scaling is by a power of 2.
float arb_fp16(float x) {
  float a = abs(x);
  if (x != x || a == 0.0) return x;
  if (a >= 65520.0) return x * 1.0e30 * 1.0e30;
  float ulp = 1.0 / 16777216.0;
  float scale = 16777216.0;
  float limit = 1.0 / 8192.0;
  for (int i = 0; i < 29; ++i) {
    if (a >= limit) {
      ulp *= 2.0;
      scale *= 0.5;
      limit *= 2.0;
    }
  }
  float q = a * scale;
  float f = floor(q);
  float d = q - f;
  if (d > 0.5 || (d == 0.5 && fract(f * 0.5) != 0.0)) f += 1.0;
  return (x < 0.0 ? -f : f) * ulp;
}
vec2 arb_fp16(vec2 v) { return vec2(arb_fp16(v.x), arb_fp16(v.y)); }
vec3 arb_fp16(vec3 v) { return vec3(arb_fp16(v.x), arb_fp16(v.y), arb_fp16(v.z)); }
vec4 arb_fp16(vec4 v) { return vec4(arb_fp16(v.x), arb_fp16(v.y), arb_fp16(v.z), arb_fp16(v.w)); }

// fx12 (NV_fragment_program 3.11.4.2): s1.10 fixed point. Values below -2048/1024 and
// above +2047/1024 (infinities too) become those, NaN becomes 0, and the rest the
// nearest multiple of 1/1024, a tie to the even one.
float arb_fx12(float x) {
  if (x != x) return 0.0;
  if (x < -2.0) return -2.0;
  if (x > 1.9990234375) return 1.9990234375;
  return arb_round_even(x * 1024.0) * 0.0009765625;
}
vec2 arb_fx12(vec2 v) { return vec2(arb_fx12(v.x), arb_fx12(v.y)); }
vec3 arb_fx12(vec3 v) { return vec3(arb_fx12(v.x), arb_fx12(v.y), arb_fx12(v.z)); }
vec4 arb_fx12(vec4 v) { return vec4(arb_fx12(v.x), arb_fx12(v.y), arb_fx12(v.z), arb_fx12(v.w)); }

// RFL (NV_fragment_program_option 3.11.5.36): the reflection of d about the axis a,
// 2 (a . d) / (a . a) * a - d, in the specification's order of operations.
vec3 arb_rfl(vec3 a, vec3 d) {
  float k = 2.0 * dot(a, d) / dot(a, a);
  return k * a - d;
}

void main() {
  vec4 h = vec4(0.0);
  vec4 t = vec4(0.0);
  vec4 r = vec4(0.0);
  vec4 arb_cc0 = vec4(0.0);  // condition code CC0: EQ everywhere
  vec4 arb_t = vec4(0.0);  // an NV result before its write

  // MULH h, fragment.color, fragment.texcoord[0];
  h = arb_fp16(arb_fp16(gl_Color) * arb_fp16(gl_TexCoord[0]));
  // ADDX r, h, -|fragment.texcoord[1]|;
  r = arb_fx12(arb_fx12(h) + arb_fx12(-abs(gl_TexCoord[1])));
  // DDX t.xy, fragment.texcoord[0];
  t.xy = dFdx(gl_TexCoord[0].xy);
  // DDYC t.zw, fragment.texcoord[0].xyxy;
  arb_t.zw = dFdy(gl_TexCoord[0].xy);
  t.zw = arb_t.zw;
  arb_cc0.zw = arb_t.zw;
  // RFL r.xyz, fragment.texcoord[1], r;
  r.xyz = arb_rfl(gl_TexCoord[1].xyz, r.xyz);
  // X2D r.zw, fragment.texcoord[0], t, fragment.color;
  r.zw = vec2(gl_TexCoord[0].x + t.x * gl_Color.x + t.y * gl_Color.y, gl_TexCoord[0].y + t.x * gl_Color.z + t.y * gl_Color.w);
  // TXD t, fragment.texcoord[0], t.xyxy, t.zwzw, texture[0], 2D;
  t = texture2DGradARB(arb_texture0, gl_TexCoord[0].xy, t.xy, t.zw);
  // KIL LT.zwzw;
  if (any(lessThan(arb_cc0.zw, vec2(0.0)))) discard;
  // SNE_SAT r.x (GE.z), r, h;
  arb_t.x = clamp(float(r.x != h.x), 0.0, 1.0);
  if (arb_cc0.z >= 0.0) r.x = arb_t.x;
  // MOVR result.color, r;
  gl_FragColor = r;
}
