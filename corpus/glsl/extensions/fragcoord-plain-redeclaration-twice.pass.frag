// [config]
// expect_result: pass
// glsl_version: 1.10
// require_extensions: GL_ARB_fragment_coord_conventions
// [end config]
// ARB_fragment_coord_conventions 4.3.x.1: "in vec4 gl_FragCoord; // redeclaration that changes nothing is allowed"; a second redeclaration with the same (no) qualifiers may follow a use, only the first must precede every use
#version 110
#extension GL_ARB_fragment_coord_conventions : require
in vec4 gl_FragCoord;
vec4 position() { return gl_FragCoord; }
in vec4 gl_FragCoord;
void main()
{
    gl_FragColor = position();
}
