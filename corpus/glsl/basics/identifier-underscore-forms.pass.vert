// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.7 "identifier: nondigit / identifier nondigit / identifier digit"
// 3.6 "In addition, all identifiers containing two consecutive underscores (__) are reserved as possible future keywords." (single underscores are fine)
#version 110
float _a = 1.0;
float a_ = 1.0;
float _ = 1.0;
float a_b_c = 1.0;
float _1 = 1.0;
float _A_B_ = 1.0;
void main()
{
    gl_Position = vec4(_a * a_ * _ * a_b_c * _1 * _A_B_);
}
