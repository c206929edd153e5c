#version 110
uniform vec3 light;
varying vec3 normal;
void main()
{
    float d = max(dot(normalize(normal), light), 0.0);
    gl_FragColor = vec4(vec3(d), 1.0);
}
