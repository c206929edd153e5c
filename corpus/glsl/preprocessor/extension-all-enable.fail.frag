// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "enable ... Warn on the #extension if the extension extension_name is not supported. Give an error on the #extension if all is specified."
#extension all : enable
void main()
{
    gl_FragColor = vec4(0.0);
}
