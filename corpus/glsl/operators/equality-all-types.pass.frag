// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.9: "The equality operators equal (==), and not equal (!=) operate on all types except arrays. They result in a scalar Boolean."
uniform vec3 a;
uniform vec3 b;
uniform mat2 m;
uniform ivec2 i;
uniform bvec4 bv;
void main()
{
    bool e = a == b;
    bool f = m != mat2(1.0);
    bool g = i == ivec2(1, 2);
    bool h = bv != bvec4(false);
    bool k = e == f;
    gl_FragColor = vec4(float(e), float(f), float(g && h), float(k));
}
