// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.3.5 "The uniform qualifier can be used with any of the basic data types, or when declaring a variable whose type is a structure, or an array of any of these."
uniform vec4 color;
uniform sampler2D tex;
void main()
{
    gl_FragColor = color * texture2D(tex, gl_TexCoord[0].xy);
}
