// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.3.6 "The varying qualifier can be used only with the data types float, vec2, vec3, vec4, mat2, mat3, and mat4, or arrays of these. Structures cannot be varying."
// 4.3.6 "A fragment shader may read from varying variables and the value read will be the interpolated value"
varying float f;
varying vec2 v2;
varying vec3 v3;
varying vec4 v4;
varying mat2 m2;
varying mat3 m3;
varying mat4 m4;
varying vec4 array[2];
void main()
{
    gl_FragColor = m4 * v4 + vec4(m3 * v3, f) + vec4(m2 * v2, array[1].xy);
}
