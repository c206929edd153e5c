// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 8.2: "pow (genType x, genType y)", "exp", "log", "exp2", "log2", "sqrt", "inversesqrt"
#version 110
uniform vec3 v;
uniform float f;
void main()
{
    vec3 a = pow(v, v) + exp(v) + log(v) + exp2(v) + log2(v) + sqrt(v) + inversesqrt(v);
    float b = pow(f, 2.0) + inversesqrt(f);
    gl_FragColor = vec4(a, b);
}
