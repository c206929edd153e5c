// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.5: "uniform gl_FogParameters gl_Fog;"; 4.3.5: "All uniform variables are read-only"
#version 110
void main()
{
    gl_Fog.density = 1.0;
    gl_FragColor = gl_Fog.color;
}
