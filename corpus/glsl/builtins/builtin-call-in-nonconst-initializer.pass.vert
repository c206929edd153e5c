// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 8: built-in functions are ordinary expressions; 4.3.2 restricts only const initializers ("Constructors may be used in such expressions, but function calls may not.")
const float k = float(2) * 0.25;
void main()
{
    float s = sin(k);
    vec3 n = normalize(vec3(1.0, 2.0, 3.0));
    gl_Position = vec4(n, s);
}
