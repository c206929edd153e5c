#version 450
// Shaped like the Vulkan translation of an ARB fragment program: the GL state it reads in a
// uniform block, one combined sampler per texture unit and target, varyings and results at
// locations.
layout(std140, set = 0, binding = 0) uniform ArbFragmentState {
  vec4 fog_color;   // state.fog.color
  vec4 fog_params;  // state.fog.params
  vec4 env[2];      // program.env[0..1]
} state;
layout(set = 0, binding = 1) uniform sampler2D texture0;        // texture[0], 2D
layout(set = 0, binding = 2) uniform samplerCube texture1;      // texture[1], CUBE
layout(set = 0, binding = 3) uniform sampler2DShadow texture2;  // texture[2], SHADOW2D
layout(set = 0, binding = 4) uniform sampler3D texture3;        // texture[3], 3D

layout(location = 0) in vec4 fragment_color;      // fragment.color
layout(location = 1) in vec4 fragment_texcoord0;  // fragment.texcoord[0]

layout(location = 0) out vec4 result_color;  // result.color

void main() {
  vec4 R0, R1, R2, R3;
  // TXP R0, fragment.texcoord[0], texture[0], 2D;
  R0 = textureProj(texture0, fragment_texcoord0);
  // TEX R1, fragment.texcoord[0], texture[1], CUBE;
  R1 = texture(texture1, fragment_texcoord0.xyz);
  // TEX R2, fragment.texcoord[0], texture[2], SHADOW2D;
  R2 = vec4(texture(texture2, fragment_texcoord0.xyz));
  // TXB R3, fragment.texcoord[0], texture[3], 3D;
  R3 = texture(texture3, fragment_texcoord0.xyz, fragment_texcoord0.w);
  // KIL R0;
  if (any(lessThan(R0, vec4(0.0)))) discard;
  // MAD R0, R0, R1, R3; MUL R0, R0, R2; MUL R0, R0, fragment.color;
  R0 = (R0 * R1 + R3) * R2 * fragment_color;
  // LRP R0.xyz, fog factor, R0, state.fog.color; (OPTION ARB_fog_linear)
  float fog = clamp((state.fog_params.z - gl_FragCoord.z / gl_FragCoord.w) * state.fog_params.w,
                    0.0, 1.0);
  R0.xyz = mix(state.fog_color.xyz, R0.xyz, fog);
  // MOV_SAT result.color, R0; MOV result.depth.z, fragment.position.z;
  result_color = clamp(R0 + state.env[0], 0.0, 1.0);
  gl_FragDepth = gl_FragCoord.z;
}
