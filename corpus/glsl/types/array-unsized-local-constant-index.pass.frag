// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.9 "Variables of the same type can be aggregated into arrays by declaring a name followed by brackets ( [ ] ) enclosing an optional size."
// 4.1.9 "If an array is indexed with an expression that is not an integral constant expression or passed as an argument to a function, then its size must be declared before any such use."
void main()
{
    vec4 colors[];
    colors[0] = vec4(1.0);
    colors[2] = vec4(0.5);
    gl_FragColor = colors[0] * colors[2];
}
