// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.2 "Functions names are always identifiable as function names based on context, and they have their own name space."
void main()
{
    float sin = 0.5;
    float cos = 0.25;
    gl_FragColor = vec4(sin(sin), cos(cos), 0.0, 1.0);
}
