// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3.5 "The uniform qualifier can be used with any of the basic data types, or when declaring a variable whose type is a structure, or an array of any of these."
uniform void nothing;
void main()
{
    gl_Position = vec4(0.0);
}
