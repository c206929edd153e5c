// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 1.1 "3.6 ... clarified that the listed keywords and reserved words are the only ones." (C/C++ keywords not listed are plain identifiers)
float char = 1.0;
float signed = 1.0;
float auto = 1.0;
float register = 1.0;
float new = 1.0;
float delete = 1.0;
float private = 1.0;
float protected = 1.0;
float virtual = 1.0;
float operator = 1.0;
float friend = 1.0;
float throw = 1.0;
float try = 1.0;
float catch = 1.0;
void main()
{
    gl_FragColor = vec4(char * signed * auto * register * new * delete * private * protected
                        * virtual * operator * friend * throw * try * catch);
}
