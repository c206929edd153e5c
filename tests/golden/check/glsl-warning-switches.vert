// ARGS: -Wno-glsl-reserved-identifier -Werror=glsl-global-initializer
uniform float u;
float my__value = u;
void main() { gl_Position = vec4(my__value); }
