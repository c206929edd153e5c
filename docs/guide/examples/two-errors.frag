#version 110
void main()
{
    float a = brightness;
    vec3 c = vec4(a);
    gl_FragColor = vec4(c, 1.0);
}
