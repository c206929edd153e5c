#version 110
// ARB fragment program translated to GLSL 1.10 by arbiter.
// OPTION ARB_fragment_program_shadow: shadow samplers.

uniform sampler2D arb_texture0;  // texture[0], 2D
uniform sampler2DShadow arb_texture1;  // texture[1], SHADOW2D

void main() {
  vec4 base = vec4(0.0);
  vec4 lit = vec4(0.0);

  // TEX base, fragment.texcoord[0], texture[0], 2D;
  base = texture2D(arb_texture0, gl_TexCoord[0].xy);
  // TXP lit, fragment.texcoord[1], texture[1], SHADOW2D;
  lit = shadow2DProj(arb_texture1, gl_TexCoord[1]);
  // MAD lit, lit.x, 0.7, 0.3;
  lit = lit.xxxx * vec4(0.7) + vec4(0.3);
  // MUL result.color, base, lit;
  gl_FragColor = base * lit;
}
