// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.3: the call's type "will be the type that was used to declare or define the function"; 5.8: assignment needs the same type
#version 110
vec2 two()
{
    return vec2(2.0);
}
void main()
{
    vec3 v = two();
    gl_FragColor = vec4(v, 1.0);
}
