// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.5: "To form an l-value, swizzling must be applied to an l-value of vector type"
#version 110
void main()
{
    vec4(1.0).x = 2.0;
    gl_FragColor = vec4(1.0);
}
