// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.4.2: "If more components are provided in the last used argument to a constructor than are needed to initialize the constructed value, the left most components of that argument are used, and the remaining ones are ignored."
#version 110
uniform vec2 a;
uniform vec3 b;
void main()
{
    vec3 v = vec3(a, b);
    gl_FragColor = vec4(v, 1.0);
}
