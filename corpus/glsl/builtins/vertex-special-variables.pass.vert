// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 7.1: "vec4 gl_Position; // must be written to", "float gl_PointSize; // may be written to", "vec4 gl_ClipVertex; // may be written to"; "Any of these variables can be read back by the shader after writing to them"
#version 110
void main()
{
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
    gl_PointSize = 2.0;
    gl_ClipVertex = gl_ModelViewMatrix * gl_Vertex;
    gl_Position.z = gl_Position.z + gl_PointSize * 0.0 + gl_ClipVertex.w * 0.0;
}
