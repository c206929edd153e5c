// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.8: "lvalue op= expression is equivalent to lvalue = lvalue op expression and the l-value and expression must satisfy the semantic requirements of both op and equals (=)."
uniform mat3 m;
void main()
{
    vec3 v = vec3(1.0);
    v *= m;
    v *= 2.0;
    v += vec3(1.0);
    ivec2 iv = ivec2(3);
    iv *= 2;
    iv /= ivec2(3, 1);
    mat3 n = m;
    n *= m;
    n /= 2.0;
    gl_Position = vec4(v + n[0] + vec3(float(iv.x)), 1.0);
}
