#extension GL_NV_shadow_samplers_cube : require
// An extension arbiter does not know: 3.3 makes require an error (enable, warn and disable
// only warn).
void main() { gl_FragColor = vec4(1.0); }
