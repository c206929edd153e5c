// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: "one can be a scalar float and the other a float vector or matrix, or one can be a scalar integer and the other an integer vector." (vec3 * int is neither)
uniform vec3 v;
void main()
{
    vec3 w = v * 2;
    gl_FragColor = vec4(w, 1.0);
}
