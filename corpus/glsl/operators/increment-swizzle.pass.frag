// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.9: "For post- and pre-increment and decrement, the expression must be one that could be assigned to (an l-value)."; 5.8: swizzles without repeated fields are l-values
#version 110
void main()
{
    vec4 v = vec4(0.0);
    v.xy++;
    --v.w;
    gl_FragColor = v;
}
