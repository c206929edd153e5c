// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 6.1: "A shader can redefine built-in functions."; 8: "User code can replace built-in functions with their own if they choose, by simply re-declaring and defining the same name and argument list."
#version 110
float sin(float x)
{
    return x;
}
void main()
{
    gl_FragColor = vec4(sin(0.5));
}
