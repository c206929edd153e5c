// ARGS: --vectors 8
// GLSL verify: pow of a negative base and a division by zero are undefined (GLSL 1.10 4.1.4,
// 8.2); where the engines differ on them the probe names the first place, and nothing else.
varying vec4 k;
void main()
{
    gl_FragColor = vec4(pow(k.x, k.y), k.z / k.w, k.x * k.y + k.z, 1.0);
}
