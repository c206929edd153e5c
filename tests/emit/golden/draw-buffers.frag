#version 110
// ARB fragment program translated to GLSL 1.10 by arbiter.
// OPTION ARB_precision_hint_nicest: a hint, nothing to translate.

uniform sampler2D arb_texture0;  // texture[0], 2D

void main() {
  vec4 c = vec4(0.0);
  vec4 arb_color0 = vec4(0.0);  // result.color[0], before fog
  vec4 arb_color1 = vec4(0.0);  // result.color[1], before fog
  vec4 arb_color2 = vec4(0.0);  // result.color[2], before fog

  // TEX c, fragment.texcoord[0], texture[0], 2D;
  c = texture2D(arb_texture0, gl_TexCoord[0].xy);
  // MUL result.color[0], c, fragment.color;
  arb_color0 = c * gl_Color;
  // MOV result.color[1], fragment.texcoord[0];
  arb_color1 = gl_TexCoord[0];
  // MOV_SAT result.color[2].xyz, -c;
  arb_color2.xyz = clamp(-c.xyz, 0.0, 1.0);
  // MOV result.depth.z, fragment.position.z;
  gl_FragDepth = gl_FragCoord.z;

  // OPTION ARB_fog_exp2: f = exp(-(density * c)^2), c = gl_FogFragCoord
  float arb_fog_dc = gl_Fog.density * gl_FogFragCoord;
  float arb_fog = clamp(exp(-(arb_fog_dc * arb_fog_dc)), 0.0, 1.0);
  gl_FragData[0] = vec4(mix(clamp(gl_Fog.color.rgb, 0.0, 1.0), clamp(arb_color0.rgb, 0.0, 1.0), arb_fog), clamp(arb_color0.a, 0.0, 1.0));
  gl_FragData[1] = vec4(mix(clamp(gl_Fog.color.rgb, 0.0, 1.0), clamp(arb_color1.rgb, 0.0, 1.0), arb_fog), clamp(arb_color1.a, 0.0, 1.0));
  gl_FragData[2] = vec4(mix(clamp(gl_Fog.color.rgb, 0.0, 1.0), clamp(arb_color2.rgb, 0.0, 1.0), arb_fog), clamp(arb_color2.a, 0.0, 1.0));
}
