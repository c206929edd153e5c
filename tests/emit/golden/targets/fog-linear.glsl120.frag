#version 120
// ARB fragment program translated to GLSL 1.20 by arbiter.

uniform sampler2D arb_texture0;  // texture[0], 2D

void main() {
  vec4 base = vec4(0.0);
  vec4 arb_color = vec4(0.0);  // result.color, before fog

  // TEX base, fragment.texcoord[0], texture[0], 2D;
  base = texture2D(arb_texture0, gl_TexCoord[0].xy);
  // MUL result.color, base, fragment.color;
  arb_color = base * gl_Color;

  // OPTION ARB_fog_linear: f = (end - c) / (end - start), c = gl_FogFragCoord
  float arb_fog = clamp((gl_Fog.end - gl_FogFragCoord) / (gl_Fog.end - gl_Fog.start), 0.0, 1.0);
  gl_FragColor = vec4(mix(clamp(gl_Fog.color.rgb, 0.0, 1.0), clamp(arb_color.rgb, 0.0, 1.0), arb_fog), clamp(arb_color.a, 0.0, 1.0));
}
