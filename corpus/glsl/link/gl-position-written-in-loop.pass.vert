// [config]
// expect_result: pass
// glsl_version: 1.10
// check_link: true
// [end config]
// Section 7.1: gl_Position "can be written at any time during shader execution." "If they are written more than once, it is the last value written that is consumed"
void main()
{
    for (int i = 0; i < 2; i++)
        gl_Position = ftransform() * float(i);
}
