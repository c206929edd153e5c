// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.8: "L-values must be writable." and "constants cannot be l-values"; 4.3.2: "It is an error to write to a const variable outside of its declaration"
const float c = 1.0;
void main()
{
    c = 2.0;
    gl_Position = vec4(c);
}
