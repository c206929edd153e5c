// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.3: "Expressions for condition-expression must evaluate to a Boolean."; 9: "condition: expression | fully_specified_type IDENTIFIER EQUAL initializer"
void main()
{
    int n = 3;
    while (int k = n) {
        n--;
    }
    gl_Position = vec4(float(n));
}
