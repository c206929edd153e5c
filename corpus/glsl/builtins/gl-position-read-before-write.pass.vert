// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 7.1: "Reading them before writing them results in undefined behavior." (undefined, not an error); "Compilers may generate a diagnostic message if they detect gl_Position is not written, or read before being written"
void main()
{
    vec4 old = gl_Position;
    gl_Position = ftransform() + old * 0.0;
}
