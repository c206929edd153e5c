// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.3: the built-in attributes are gl_MultiTexCoord0 through gl_MultiTexCoord7 only
void main()
{
    gl_Position = gl_MultiTexCoord8;
}
