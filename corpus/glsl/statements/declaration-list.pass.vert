// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 9: "init_declarator_list: single_declaration | init_declarator_list COMMA IDENTIFIER | ... COMMA IDENTIFIER LEFT_BRACKET constant_expression RIGHT_BRACKET | ... COMMA IDENTIFIER EQUAL initializer"
#version 110
void main()
{
    float a = 1.0, b, c[2], d = a * 2.0;
    b = a;
    c[0] = b; c[1] = d;
    gl_Position = vec4(a, b, c[1], d);
}
