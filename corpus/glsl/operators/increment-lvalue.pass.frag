// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.9: "The arithmetic unary operators negate (-), post- and pre-increment and decrement (-- and ++) that operate on integer or floating-point values (including vectors and matrices)."
#version 110
void main()
{
    int i = 0;
    float f = 0.0;
    vec2 v = vec2(0.0);
    mat2 m = mat2(0.0);
    i++;
    ++f;
    v--;
    --m;
    ivec3 iv = ivec3(1);
    iv++;
    float g = -f + float(-i);
    gl_FragColor = vec4(v, m[0][0] + g, float(iv.x));
}
