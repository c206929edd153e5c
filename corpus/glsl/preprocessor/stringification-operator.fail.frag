// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3: "There are no number sign based operators (no #, #@, ##, etc.), nor is there a sizeof operator."
#define NAME(x) #x
void main()
{
    gl_FragColor = vec4(1.0);
}
