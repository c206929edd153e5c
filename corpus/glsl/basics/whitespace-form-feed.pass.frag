// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.1 "White space: the space character, horizontal tab, vertical tab, form feed, carriage-return, and line-feed."
voidmain()
{
    gl_FragColor=vec4(0.0);
}
