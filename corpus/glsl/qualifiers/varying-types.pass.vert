// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.3.6 "The varying qualifier can be used only with the data types float, vec2, vec3, vec4, mat2, mat3, and mat4, or arrays of these. Structures cannot be varying."
#version 110
varying float f;
varying vec2 v2;
varying vec3 v3;
varying vec4 v4;
varying mat2 m2;
varying mat3 m3;
varying mat4 m4;
varying vec4 array[2];
varying float farray[3];
void main()
{
    f = 1.0;
    v2 = vec2(f);
    v3 = vec3(f);
    v4 = vec4(f);
    m2 = mat2(f);
    m3 = mat3(f);
    m4 = mat4(f);
    array[1] = v4;
    farray[2] = f;
    gl_Position = v4;
}
