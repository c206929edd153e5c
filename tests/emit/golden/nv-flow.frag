#version 110
#extension GL_ARB_shader_texture_lod : require
// ARB fragment program translated to GLSL 1.10 by arbiter.

uniform sampler2D arb_texture0;  // texture[0], 2D

void main() {
  vec4 t = vec4(0.0);
  vec4 u = vec4(0.0);
  int arb_a0_1 = 0;  // A0.x of a LOOP block
  vec4 arb_cc0 = vec4(0.0);  // condition code CC0: EQ everywhere
  int arb_incr1 = 0;  // its increment
  int arb_loop1 = 0;  // loop count
  int arb_loop2 = 0;  // loop count
  vec4 arb_t = vec4(0.0);  // an NV result before its write

  // MOV t, 0;
  t = vec4(0.0);
  // MOVC u, fragment.color;
  arb_t = gl_Color;
  u = arb_t;
  arb_cc0 = arb_t;
  // IF GT.x;
  if (arb_cc0.x > 0.0) {
    // LOOP loop;
    arb_loop1 = 4;
    arb_a0_1 = 0;
    arb_incr1 = 1;
    for (; arb_loop1 > 0; --arb_loop1) {
      // ADD t, t, fragment.texcoord[1];
      t = t + gl_TexCoord[1];
      // SUBC u.w, u, 0.25;
      arb_t.w = u.w - 0.25;
      u.w = arb_t.w;
      arb_cc0.w = arb_t.w;
      // BRK (LE.w);
      if (arb_cc0.w <= 0.0) break;
      arb_a0_1 += arb_incr1;
    }  // ENDLOOP;
  } else {  // ELSE;
    // REP loop.x;
    arb_loop2 = 4;
    for (; arb_loop2 > 0; --arb_loop2) {
      // ADD t, t, 0.5;
      t = t + vec4(0.5);
    }  // ENDREP;
  }  // ENDIF;
  // NRM u, t;
  u = vec4(t.xyz * inversesqrt(dot(t.xyz, t.xyz)), 1.0);
  // DIV u.xy, u, t.w;
  u.xy = u.xy / t.w;
  // DP2A u.w, u, t, t.z;
  u.w = dot(u.xy, t.xy) + t.z;
  // TXL t, u, texture[0], 2D;
  t = texture2DLod(arb_texture0, u.xy, u.w);
  // MUL_SSAT result.color, t, fragment.facing.x;
  gl_FragColor = clamp(t * vec4((gl_FrontFacing ? 1.0 : -1.0), 0.0, 0.0, 1.0).xxxx, -1.0, 1.0);
}
