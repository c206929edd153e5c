// [config]
// expect_result: fail
// glsl_version: 1.10
// check_link: true
// [end config]
// 7.x and 6.1: "each program ... must have a main()" (judged as a program: check_link)
#version 110
vec3 tint(vec3 c) { return c * 0.5; }
