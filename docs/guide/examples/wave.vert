#version 110
uniform float time;
varying vec3 normal;
void main()
{
    vec4 p = gl_Vertex;
    p.y += 0.1 * sin(time + p.x);
    normal = gl_NormalMatrix * gl_Normal;
    gl_Position = gl_ModelViewProjectionMatrix * p;
}
