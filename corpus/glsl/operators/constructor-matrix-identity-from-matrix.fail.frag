// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.4.2: "However, construction of a matrix from other matrices is currently reserved for future use."
uniform mat2 m;
void main()
{
    mat2 n = mat2(m);
    gl_FragColor = vec4(n[0], n[1]);
}
