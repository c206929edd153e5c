// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.5: "the following uniform variables are built into the OpenGL Shading Language"; 4.3.5: "All uniform variables are read-only"
void main()
{
    gl_ModelViewMatrix = mat4(1.0);
    gl_Position = gl_ModelViewMatrix * gl_Vertex;
}
