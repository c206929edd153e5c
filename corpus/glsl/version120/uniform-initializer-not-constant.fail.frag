// [config]
// expect_result: fail
// glsl_version: 1.20
// [end config]
// 1.20 4.3.5: "uniform variables ... initializers ... must be constant expressions" (a uniform initialized from another uniform)
#version 120
uniform float a;
uniform float b = a;
void main()
{
    gl_FragColor = vec4(b);
}
