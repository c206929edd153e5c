// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 1.10 chapter 9: a declaration may be a fully_specified_type without a declarator; with the
// qualifier `varying` or `attribute` it declares the structure type and no variable, so no
// varying or attribute of structure type exists (4.3.4, 4.3.6). (piglit CorrectFull.vert)
varying struct Light {
    float intensity;
};
attribute struct Material {
    float shininess;
};
uniform Light light;
void main()
{
    gl_Position = vec4(light.intensity);
}
