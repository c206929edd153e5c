// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 9: "external_declaration: function_definition | declaration"; a declaration is "function_prototype SEMICOLON" or "init_declarator_list SEMICOLON", so a lone ";" is not a global declaration
void main()
{
    gl_Position = vec4(0.0);
};
