// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "The #version directive must occur in a shader before anything else, except for comments and white space."
/* a block comment */
   	
// a line comment
   #   version   110
void main()
{
    gl_FragColor = vec4(0.0);
}
