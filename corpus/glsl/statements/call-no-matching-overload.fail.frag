// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.1: "an exact match for the function's signature is sought ... All expected combination of inputs and outputs must be defined as separate functions."
#version 110
float f(vec3 v) { return v.x; }
float f(float x) { return x; }
void main()
{
    gl_FragColor = vec4(f(vec2(1.0)));
}
