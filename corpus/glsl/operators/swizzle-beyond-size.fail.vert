// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.5: "Accessing components beyond those declared for the vector type is an error so, for example: vec2 pos; ... pos.z // is illegal"
#version 110
uniform vec2 pos;
void main()
{
    float z = pos.z;
    gl_Position = vec4(pos, z, 1.0);
}
