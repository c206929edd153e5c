// [config]
// expect_result: fail
// glsl_version: 1.20
// require_extensions: GL_ARB_fragment_coord_conventions
// [end config]
// ARB_fragment_coord_conventions 4.3.x.1: gl_FragCoord is redeclared as "in vec4 gl_FragCoord"; a vec3 is another variable of a reserved name
#version 120
#extension GL_ARB_fragment_coord_conventions : require
in vec3 gl_FragCoord;
void main()
{
    gl_FragColor = vec4(gl_FragCoord.xyz, 1.0);
}
