// [config]
// expect_result: fail
// glsl_version: 1.10
// check_link: true
// [end config]
// Section 6.1: "A shader need not contain a function named main, but one shader in a set of shaders linked together to form a single program must." (linked alone, this shader has no main)
float helper(float x)
{
    return x * 2.0;
}
