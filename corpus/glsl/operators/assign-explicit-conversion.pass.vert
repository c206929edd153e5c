// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.8: "All desired type-conversions must be specified explicitly via a constructor."
void main()
{
    float f;
    f = float(1);
    int i;
    i = int(2.5);
    gl_Position = vec4(f, float(i), 0.0, 1.0);
}
