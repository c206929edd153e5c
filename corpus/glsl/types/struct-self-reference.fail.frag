// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.8 "Member types must be either already defined (there are no forward references), or defined in-place by embedding another struct definition."
struct Node {
    float value;
    Node next;
};
void main()
{
    gl_FragColor = vec4(0.0);
}
