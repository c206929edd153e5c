// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.6: "The following varying variables are available to read from in a fragment shader"; 4.3.6: "A fragment shader can not write to a varying variable."
void main()
{
    gl_TexCoord[0] = vec4(0.0);
    gl_FragColor = gl_TexCoord[0];
}
