// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.1 "In general, the language's use of this character set is case sensitive."
#version 110
void main()
{
    float value = 1.0;
    float Value = 2.0;
    float VALUE = 3.0;
    float Float = 4.0;
    float Vec4 = 5.0;
    gl_Position = vec4(value, Value, VALUE, Float + Vec4);
}
