// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.8 "struct-definition : qualifier(opt) struct name(opt) { member-list } declarators(opt) ;"
// 4.2 "Otherwise, if it is declared as a statement within a compound statement, it is scoped to the end of that compound statement."
void main()
{
    struct Local {
        vec4 color;
    } l;
    l.color = vec4(1.0);
    gl_FragColor = l.color;
}
