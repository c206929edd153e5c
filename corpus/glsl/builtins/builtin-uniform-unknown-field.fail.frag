// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.5: "struct gl_FogParameters { vec4 color; float density; float start; float end; float scale; };" (no other fields)
void main()
{
    gl_FragColor = gl_Fog.colour;
}
