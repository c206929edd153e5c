// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.3: "genType abs (genType x)" where genType is float, vec2, vec3 or vec4 (integer overloads are not part of 1.10)
uniform int i;
void main()
{
    int a = abs(i);
    gl_FragColor = vec4(float(a));
}
