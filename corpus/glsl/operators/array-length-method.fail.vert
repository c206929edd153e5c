// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.2: "Array elements are accessed using the array subscript operator ( [ ] ). This is the only operator that operates on arrays." (no .length() method in 1.10)
uniform vec4 w[3];
void main()
{
    gl_Position = vec4(float(w.length()));
}
