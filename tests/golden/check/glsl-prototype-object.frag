vec4 shade(vec4 c);
void main() { gl_FragColor = shade(gl_Color); }
