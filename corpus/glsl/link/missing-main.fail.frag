// [config]
// expect_result: fail
// glsl_version: 1.10
// check_link: true
// [end config]
// Section 6.1: "one shader in a set of shaders linked together to form a single program must" contain main
#version 110
uniform vec4 c;
vec4 shade()
{
    return c;
}
