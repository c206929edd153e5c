#version 120
// ARB fragment program translated to GLSL 1.20 by arbiter.

varying vec4 gl_TexCoord[3];
uniform sampler2D arb_texture0;  // texture[0], 2D

void main() {
  vec4 t = vec4(0.0);
  vec4 arb_color = vec4(0.0);  // result.color, before fog

  // TEX t, fragment.texcoord[0], texture[0], 2D;
  t = texture2D(arb_texture0, gl_TexCoord[0].xy);
  // MAD t, t, fragment.texcoord[2], fragment.color;
  t = t * gl_TexCoord[2] + gl_Color;
  // MOV result.color, t;
  arb_color = t;

  // OPTION ARB_fog_linear: f = (end - c) / (end - start), c = gl_FogFragCoord
  float arb_fog = clamp((gl_Fog.end - gl_FogFragCoord) / (gl_Fog.end - gl_Fog.start), 0.0, 1.0);
  gl_FragColor = vec4(mix(clamp(gl_Fog.color.rgb, 0.0, 1.0), clamp(arb_color.rgb, 0.0, 1.0), arb_fog), clamp(arb_color.a, 0.0, 1.0));
}
