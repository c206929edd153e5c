// [config]
// expect_result: pass
// glsl_version: 1.20
// [end config]
// 1.20 4.3: "Initializers may only be used in declarations of globals with no storage qualifier, a const qualifier, or a uniform qualifier." (1.20 drops 1.10's "Such initializers must have constant type")
#version 120
uniform float scale;
float s = scale * 2.0;
void main()
{
    gl_Position = vec4(s);
}
