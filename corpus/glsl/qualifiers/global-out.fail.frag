// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3 "Global variables can only use the qualifiers const, attribute, uniform, or varying. Only one may be specified."
out vec4 color;
void main()
{
    color = vec4(1.0);
}
