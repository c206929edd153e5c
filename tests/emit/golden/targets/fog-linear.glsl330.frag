#version 330 core
// ARB fragment program translated to GLSL 3.30 core by arbiter.

in vec4 arb_color0;
in float arb_fogcoord;
in vec4 arb_texcoord0;
uniform vec4 arb_state_fog_color;  // state.fog.color
uniform vec4 arb_state_fog_params;  // state.fog.params
uniform sampler2D arb_texture0;  // texture[0], 2D
layout(location = 0) out vec4 arb_fragcolor0;  // result.color

void main() {
  vec4 base = vec4(0.0);
  vec4 arb_color = vec4(0.0);  // result.color, before fog

  // TEX base, fragment.texcoord[0], texture[0], 2D;
  base = texture(arb_texture0, arb_texcoord0.xy);
  // MUL result.color, base, fragment.color;
  arb_color = base * arb_color0;

  // OPTION ARB_fog_linear: f = (end - c) / (end - start), c = arb_fogcoord
  float arb_fog = clamp((arb_state_fog_params.z - arb_fogcoord) / (arb_state_fog_params.z - arb_state_fog_params.y), 0.0, 1.0);
  arb_fragcolor0 = vec4(mix(clamp(arb_state_fog_color.rgb, 0.0, 1.0), clamp(arb_color.rgb, 0.0, 1.0), arb_fog), clamp(arb_color.a, 0.0, 1.0));
}
