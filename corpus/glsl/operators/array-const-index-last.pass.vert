// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.2: "Array indices start at zero." An index of size-1 is the last element.
uniform vec4 w[2];
const int last = 1;
void main()
{
    gl_Position = w[last] + w[last - 1];
}
