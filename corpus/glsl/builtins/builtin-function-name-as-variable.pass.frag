// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 4.2: "All variables in the same scope share the same name space. Functions names are always identifiable as function names based on context, and they have their own name space."
#version 110
void main()
{
    float sin = 0.5;
    gl_FragColor = vec4(sin(sin));
}
