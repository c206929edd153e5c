// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.4.1: "float(int) // converts an integer value to a float" and "int(float) // converts a float value to an int"
uniform int a;
uniform float b;
void main()
{
    float f = float(a);
    int i = int(b);
    bool t = bool(a);
    bool u = bool(b);
    float g = float(t) + float(i) + float(int(u));
    gl_Position = vec4(f, g, 0.0, 1.0);
}
