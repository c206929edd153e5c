// [config]
// expect_result: pass
// glsl_version: 1.20
// [end config]
// 1.20 5.4.4 "Array Constructors": float[3](1.0, 2.0, 3.0); 5.7: "The length method may be applied to arrays"; 4.1.9: an array declared without a size takes the size of its initializer
#version 120
const float weights[] = float[](0.25, 0.5, 0.25);
void main()
{
    float sum = 0.0;
    for (int i = 0; i < weights.length(); i++)
        sum += weights[i];
    gl_Position = vec4(sum);
}
