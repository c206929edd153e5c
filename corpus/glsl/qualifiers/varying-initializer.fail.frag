// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3 "Declarations of globals without a qualifier, or with just the const qualifier may include initializers ... Such initializers must have constant type."
varying float fog = 0.0;
void main()
{
    gl_FragColor = vec4(fog);
}
