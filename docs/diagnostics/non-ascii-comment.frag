#version 110
// café: a comment in UTF-8
void main()
{
    gl_FragColor = vec4(1.0);
}
