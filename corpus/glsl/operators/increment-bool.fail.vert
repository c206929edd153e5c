// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: increment and decrement "operate on integer or floating-point values (including vectors and matrices)."
void main()
{
    bool b = false;
    b++;
    gl_Position = vec4(float(b));
}
