// [config]
// expect_result: pass
// glsl_version: 1.20
// [end config]
// 1.2: "Allow initializers on uniform declarations. The value is set at link time." 4.3: "Initializers may only be used in declarations of globals with no storage qualifier, a const qualifier, or a uniform qualifier."
#version 120
uniform vec4 tint = vec4(1.0, 0.5, 0.25, 1.0);
void main()
{
    gl_FragColor = tint;
}
