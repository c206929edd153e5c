// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: "For post- and pre-increment and decrement, the expression must be one that could be assigned to (an l-value)."; 5.8: "constants cannot be l-values"
#version 110
const int k = 1;
void main()
{
    int j = ++k;
    gl_Position = vec4(float(j));
}
