#version 120
// ARGS: -I include-lib
#extension GL_ARB_shading_language_include : require
#include "lighting.glsl"
varying vec3 normal;
void main() { gl_FragColor = vec4(lambert(normalize(normal), vec3(0, 0, 1)), 1.0); }
