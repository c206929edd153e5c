// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.9 "All basic types and structures can be formed into arrays."
uniform sampler2D samplers[2];
uniform bool flags[2];
void main()
{
    int i[2];
    float f[2];
    vec4 v[2];
    ivec3 iv[2];
    bvec2 bv[2];
    mat3 m[2];
    i[0] = 1;
    f[0] = float(i[0]);
    v[0] = vec4(f[0]);
    m[0] = mat3(f[0]);
    bv[0] = bvec2(flags[1]);
    iv[0] = ivec3(i[0]);
    gl_FragColor = v[0] + texture2D(samplers[1], m[0][0].xy);
}
