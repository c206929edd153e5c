// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3: "all ... If the extension is ... all, then the behavior must be warn or disable" (require with all is an error)
#extension all : require
void main()
{
    gl_Position = ftransform();
}
