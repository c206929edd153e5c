#version 110
#extension GL_ARB_texture_rectangle : require
// ARB fragment program translated to GLSL 1.10 by arbiter.

uniform vec4 arb_fp_env[3];  // program.env[0..2]
uniform vec4 arb_fp_local[1];  // program.local[0]
uniform sampler2D arb_texture0;  // texture[0], 2D
uniform samplerCube arb_texture1;  // texture[1], CUBE
uniform sampler2DRect arb_texture2;  // texture[2], RECT

void main() {
  vec4 a = vec4(0.0);
  vec4 b = vec4(0.0);
  vec4 c = vec4(0.0);

  // KIL fragment.texcoord[0];
  if (any(lessThan(gl_TexCoord[0], vec4(0.0)))) discard;
  // KIL -a.xyzx;
  if (any(lessThan(-a.xyzx, vec4(0.0)))) discard;
  // TXB a, fragment.texcoord[0], texture[0], 2D;
  a = texture2D(arb_texture0, gl_TexCoord[0].xy, gl_TexCoord[0].w);
  // TXP b, fragment.texcoord[1], texture[1], CUBE;
  b = textureCube(arb_texture1, gl_TexCoord[1].xyz / gl_TexCoord[1].w);
  // TEX c, fragment.texcoord[2], texture[2], RECT;
  c = texture2DRect(arb_texture2, gl_TexCoord[2].xy);
  // CMP a.xyw, -a, b, c;
  a.xyw = vec3(-a.x < 0.0 ? b.x : c.x, -a.y < 0.0 ? b.y : c.y, -a.w < 0.0 ? b.w : c.w);
  // LRP_SAT b, e.x, a, c;
  b = clamp(mix(c, a, arb_fp_env[2].xxxx), 0.0, 1.0);
  // SCS c.xy, a.w;
  c.xy = vec2(cos(a.w), sin(a.w));
  // SGE a.x, b, c;
  a.x = float(b.x >= c.x);
  // SLT a.yz, b, c.x;
  a.yz = vec2(lessThan(b.yz, c.xx));
  // POW b.w, l.x, e.y;
  b.w = pow(arb_fp_local[0].x, arb_fp_env[2].y);
  // FRC c.zw, b;
  c.zw = fract(b.zw);
  // ADD result.color, a, b;
  gl_FragColor = a + b;
}
