// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.7 "They can only be declared as function parameters or uniforms"
// 4.1.7 "Sampler types (e.g. sampler2D) are effectively opaque handles to textures."
uniform sampler1D s1;
uniform sampler2D s2;
uniform sampler3D s3;
uniform samplerCube sc;
uniform sampler1DShadow s1s;
uniform sampler2DShadow s2s;
uniform sampler2D array[2];
void main()
{
    vec4 c = texture1D(s1, 0.5) + texture2D(s2, vec2(0.5)) + texture3D(s3, vec3(0.5))
           + textureCube(sc, vec3(1.0)) + shadow1D(s1s, vec3(0.5)) + shadow2D(s2s, vec3(0.5))
           + texture2D(array[1], vec2(0.5));
    gl_FragColor = c;
}
