// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.5: "Behavior is undefined if the index is greater than or equal to the size of the vector." (undefined behaviour, not a compile error; contrast 4.1.9 which makes this illegal for arrays only)
uniform vec2 v;
void main()
{
    float f = v[2];
    gl_FragColor = vec4(f);
}
