#version 100
// ARB fragment program translated to GLSL ES 1.00 by arbiter.

#ifdef GL_FRAGMENT_PRECISION_HIGH
precision highp float;
precision highp int;
#else
#error "arbiter: exact ARB arithmetic needs highp floats in fragment shaders"
#endif

varying vec4 arb_color0;
varying float arb_fogcoord;
varying vec4 arb_texcoord0;
varying vec4 arb_texcoord2;
uniform vec4 arb_state_fog_color;  // state.fog.color
uniform vec4 arb_state_fog_params;  // state.fog.params
uniform highp sampler2D arb_texture0;  // texture[0], 2D

void main() {
  vec4 t = vec4(0.0);
  vec4 arb_color = vec4(0.0);  // result.color, before fog

  // TEX t, fragment.texcoord[0], texture[0], 2D;
  t = texture2D(arb_texture0, arb_texcoord0.xy);
  // MAD t, t, fragment.texcoord[2], fragment.color;
  t = t * arb_texcoord2 + arb_color0;
  // MOV result.color, t;
  arb_color = t;

  // OPTION ARB_fog_linear: f = (end - c) / (end - start), c = arb_fogcoord
  float arb_fog = clamp((arb_state_fog_params.z - arb_fogcoord) / (arb_state_fog_params.z - arb_state_fog_params.y), 0.0, 1.0);
  gl_FragColor = vec4(mix(clamp(arb_state_fog_color.rgb, 0.0, 1.0), clamp(arb_color.rgb, 0.0, 1.0), arb_fog), clamp(arb_color.a, 0.0, 1.0));
}
