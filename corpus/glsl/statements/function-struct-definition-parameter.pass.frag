// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 6.1: "type : any basic type, structure name, or structure definition"; 9: "parameter_declarator: type_specifier IDENTIFIER", "type_specifier: ... struct_specifier"
float get(struct P { float v; } p)
{
    return p.v;
}
void main()
{
    gl_FragColor = vec4(1.0);
}
