// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.9 "Variables of the same type can be aggregated into arrays by declaring a name followed by brackets ( [ ] ) enclosing an optional size." (the size is optional)
// 4.1.9 "If an array is indexed with an expression that is not an integral constant expression or passed as an argument to a function, then its size must be declared before any such use." (constant indices are allowed before a size is given)
#version 110
float values[];
void main()
{
    values[0] = 1.0;
    values[3] = 2.0;
    gl_Position = vec4(values[0], values[3], 0.0, 1.0);
}
