// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "If an implementation does not recognize the tokens following #pragma, then it will ignore that pragma."
// 3.3 "The STDGL pragma is used to reserve pragmas for use by future revisions of this language."
#pragma STDGL invariant(all)
#pragma STDGL something_from_the_future
void main()
{
    gl_FragColor = vec4(0.0);
}
