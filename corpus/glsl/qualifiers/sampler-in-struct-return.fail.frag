// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 1.10 4.1.7: samplers "can only be declared as function parameters or uniforms" (a structure holding one cannot be a return value; 1.20 4.1.7 says it outright)
struct Material { float shininess; sampler2D map; };
uniform Material m;
Material current() { return m; }
void main()
{
    gl_FragColor = texture2D(current().map, vec2(0.5));
}
