// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.5: component selection applies to vectors, including ivec and bvec
#version 110
uniform ivec4 iv;
uniform bvec3 bv;
void main()
{
    ivec2 a = iv.wz;
    bool b = bv.y;
    gl_FragColor = vec4(float(a.x), float(a.y), float(b), 1.0);
}
