// Texture lookups on every sampler type of GLSL 1.10, and the fragment outputs.
uniform sampler1D ramp;
uniform sampler2D maps[2];
uniform samplerCube sky;
uniform sampler2DShadow shadow_map;
uniform sampler3D unused_volume;
uniform vec4 fog_tint;
varying vec2 uv;
varying vec3 unread;

void main() {
  vec4 c = texture2D(maps[0], uv) * texture2DProj(maps[1], gl_TexCoord[0]);
  c += texture1D(ramp, uv.x) + textureCube(sky, gl_TexCoord[1].xyz);
  c *= shadow2DProj(shadow_map, gl_TexCoord[1]).r;
  gl_FragColor = mix(c, fog_tint, gl_FogFragCoord) * gl_Color;
  gl_FragDepth = gl_FragCoord.z;
}
