// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.9: "It is legal to declare an array without a size and then later re-declare the same name as an array of the same type and specify a size" (index 3 used, size 4)
uniform vec4 colors[];
void main()
{
    gl_FragColor = colors[3];
}
uniform vec4 colors[4];
