#version 110
uniform vec4 light;
varying vec4 normal;
varying vec2 uv;
void main()
{
    gl_FragColor = vec4(normal.xyz, 1.0) * light * uv.x;
}
