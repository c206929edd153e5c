// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 6.1: "type : any basic type, structure name, or structure definition" (function-prototype: type function-name(...))
struct Result { float v; } make(float x)
{
    return Result(x);
}
void main()
{
    Result r = make(1.0);
    gl_Position = vec4(r.v);
}
