// [config]
// expect_result: fail
// glsl_version: 1.10
// check_link: true
// [end config]
// Section 6.1: main is "the entry point to a shader" and "one shader in a set of shaders linked together ... must" contain it; a prototype alone is no definition
void main();
