// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 6.3: "Both the condition-expression and the init-expression can declare and initialize a variable, except in the do-while loop"; 9: "conditionopt: condition", "condition: fully_specified_type IDENTIFIER EQUAL initializer"
void main()
{
    int i = 0;
    for (; bool more = i < 3; i++) {
        gl_FragColor = vec4(float(more));
    }
}
