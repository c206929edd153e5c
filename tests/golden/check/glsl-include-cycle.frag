// ARGS: -I include-lib
#extension GL_ARB_shading_language_include : require
#include "cycle.glsl"
void main() { gl_FragColor = vec4(1.0); }
