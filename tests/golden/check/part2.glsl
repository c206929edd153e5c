void main() { gl_FragColor = tint * undefined_thing; }
