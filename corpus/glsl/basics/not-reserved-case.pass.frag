// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 1.1 "3.6 ... clarified that the listed keywords and reserved words are the only ones." (switch and default are reserved, case is not)
float case = 1.0;
void main()
{
    gl_FragColor = vec4(case);
}
