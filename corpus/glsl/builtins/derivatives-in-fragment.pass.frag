// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 8.8: "genType dFdx (genType p)", "genType dFdy (genType p)", "genType fwidth (genType p)"
void main()
{
    vec2 uv = gl_TexCoord[0].xy;
    vec2 a = dFdx(uv) + dFdy(uv) + fwidth(uv);
    float b = dFdx(uv.x) + fwidth(gl_FragCoord.z);
    gl_FragColor = vec4(a, b, 1.0);
}
