// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.3.1 "For either global or local unqualified variables, the declaration will appear to allocate memory associated with the processor it targets. This variable will provide read/write access to this allocated memory."
vec4 accumulator;
void add(vec4 v)
{
    accumulator += v;
}
void main()
{
    accumulator = vec4(0.0);
    add(vec4(0.5));
    vec4 local;
    local = accumulator;
    local.w = 1.0;
    gl_FragColor = local;
}
