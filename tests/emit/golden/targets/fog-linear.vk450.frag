#version 450
// ARB fragment program translated to GLSL 4.50 (Vulkan) by arbiter.

layout(location = 0) in vec4 arb_color0;
layout(location = 4) in float arb_fogcoord;
layout(location = 5) in vec4 arb_texcoord0;
layout(std140, set = 0, binding = 1) uniform ArbFragmentUniforms {
  vec4 arb_state_fog_color;  // state.fog.color  offset 0
  vec4 arb_state_fog_params;  // state.fog.params  offset 16
};
layout(set = 0, binding = 2) uniform sampler2D arb_texture0;  // texture[0], 2D
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
