// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.3: "genType sign (genType x)" (genType is float, vec2, vec3, vec4)
uniform int i;
void main()
{
    gl_FragColor = vec4(float(sign(i)));
}
