#version 110
varying float k;
void main() { gl_FragColor = vec4(gl_Color.rgb, k); }
