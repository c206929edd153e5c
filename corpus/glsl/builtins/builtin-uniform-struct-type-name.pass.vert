// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 7.5: "struct gl_MaterialParameters { ... }; uniform gl_MaterialParameters gl_FrontMaterial;" (the built-in structure types are declared and can name variables)
#version 110
void main()
{
    gl_MaterialParameters m = gl_FrontMaterial;
    gl_LightSourceParameters l = gl_LightSource[0];
    gl_Position = m.diffuse * l.diffuse;
}
