// ARGS: --stage frag
uniform vec4 tint;
