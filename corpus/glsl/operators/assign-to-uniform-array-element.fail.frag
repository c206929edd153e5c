// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.8: "L-values must be writable."; 4.3.5: "All uniform variables are read-only"
#version 110
uniform vec4 colors[2];
void main()
{
    colors[0] = vec4(1.0);
    gl_FragColor = colors[0];
}
