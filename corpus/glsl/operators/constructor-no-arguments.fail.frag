// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.4: "Semantically, the number of parameters must be of sufficient size and correct type to perform the initialization."
#version 110
void main()
{
    vec4 c = vec4();
    gl_FragColor = c;
}
