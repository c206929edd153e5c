#version 450
// Shaped like the Vulkan translation of an ARB fragment program with two colour results
// (ARB_draw_buffers), a 1D texture, explicit LOD and derivative lookups (NV_fragment_program2's
// TXL and TXD), front-facing selection and a swizzled, saturated result.
layout(std140, set = 0, binding = 0) uniform ArbFragmentState {
  vec4 texenv_color;  // state.texenv[0].color
  vec4 local[4];      // program.local[0..3]
} state;
layout(set = 0, binding = 1) uniform sampler1D texture0;    // texture[0], 1D
layout(set = 0, binding = 2) uniform sampler2D texture1;    // texture[1], 2D
layout(set = 0, binding = 3) uniform samplerCube texture2;  // texture[2], CUBE

layout(location = 0) in vec4 fragment_color;       // fragment.color.primary
layout(location = 1) in vec4 fragment_color_back;  // (two-sided colour)
layout(location = 3) in vec4 fragment_texcoord[2]; // fragment.texcoord[0..1]

layout(location = 0) out vec4 result_color0;  // result.color[0]
layout(location = 1) out vec4 result_color1;  // result.color[1]

void main() {
  vec4 color = gl_FrontFacing ? fragment_color : fragment_color_back;
  vec4 R0 = texture(texture0, fragment_texcoord[0].x);
  vec4 R1 = textureLod(texture1, fragment_texcoord[1].xy, fragment_texcoord[1].w);
  vec4 R2 = textureGrad(texture2, fragment_texcoord[0].xyz, dFdx(fragment_texcoord[0].xyz),
                        dFdy(fragment_texcoord[0].xyz));
  // CMP R0, R0, R1, R2; (R0 < 0 ? R1 : R2, per component)
  R0 = mix(R2, R1, lessThan(R0, vec4(0.0)));
  // POW R1.x, R0.x, state.local[1].y; RCP R1.y, R0.y;
  R1.x = exp2(state.local[1].y * log2(R0.x));
  R1.y = 1.0 / R0.y;
  result_color0 = clamp(R0.wzyx * color, 0.0, 1.0);
  result_color1 = vec4(R1.xy, state.texenv_color.zw) + state.local[int(R0.x > 0.5)];
}
