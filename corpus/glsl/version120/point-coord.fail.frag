// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 1.10 7 has no gl_PointCoord: it is added by 1.20 (1.2 "Add gl_PointCoord")
#version 110
void main()
{
    gl_FragColor = vec4(gl_PointCoord, 0.0, 1.0);
}
