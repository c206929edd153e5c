// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.4.1: "Scalar constructors with non-scalar parameters can be used to take the first element from a non-scalar. For example, the constructor float(vec3) will select the first component"
#version 110
uniform vec3 v;
uniform ivec2 iv;
void main()
{
    float f = float(v);
    int i = int(v);
    bool b = bool(iv);
    gl_Position = vec4(f, float(i), float(b), 1.0);
}
