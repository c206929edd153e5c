// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 8.4: "vec4 ftransform() For vertex shaders only ... gl_Position = ftransform()"
#version 110
void main()
{
    gl_Position = ftransform();
}
