// Shared declarations: the first string of both stages.
varying vec2 uv;
uniform vec4 tint;
