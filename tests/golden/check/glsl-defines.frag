// ARGS: -D SCALE=0.5 -D FAST -U FAST
#ifdef FAST
#error FAST was undefined by -U
#endif
void main() { gl_FragColor = vec4(SCALE); }
