#version 110
uniform sampler2D tex;
varying vec2 uv;
void main()
{
    vec3 c = texture2D(tex, uv);
    gl_FragColor = vec4(c, 1.0);
}
