// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: expressions include "Variable names of all types, except array names not followed by a subscript."; 5.4: "Constructors are not built-in functions."
void main()
{
    float a[2];
    a[0] = 1.0; a[1] = 2.0;
    vec2 v = vec2(a);
    gl_Position = vec4(v, 0.0, 1.0);
}
