#version 110
void main()
{
    float café = 1.0;
    gl_FragColor = vec4(café);
}
