// [config]
// expect_result: pass
// glsl_version: 1.20
// [end config]
// 1.20 4.3.3: a constant expression is "an expression formed by an operator on operands that are all constant expressions" (the sequence operator among them)
#version 120
void main()
{
    const vec4 v = (vec4(1.0), vec4(2.0));
    const float f = v[0, 1];
    gl_FragColor = v * f;
}
