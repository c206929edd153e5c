// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 7.5: "uniform mat4 gl_ModelViewMatrix; ... uniform mat4 gl_TextureMatrix[gl_MaxTextureCoords]; uniform mat3 gl_NormalMatrix; ... gl_TextureMatrixInverseTranspose[gl_MaxTextureCoords]; uniform float gl_NormalScale;"
#version 110
void main()
{
    mat4 a = gl_ModelViewMatrix * gl_ProjectionMatrix * gl_ModelViewProjectionMatrix * gl_TextureMatrix[0];
    mat4 b = gl_ModelViewMatrixInverse * gl_ProjectionMatrixInverse
           * gl_ModelViewProjectionMatrixInverse * gl_TextureMatrixInverse[1];
    mat4 c = gl_ModelViewMatrixTranspose * gl_ProjectionMatrixTranspose
           * gl_ModelViewProjectionMatrixTranspose * gl_TextureMatrixTranspose[0];
    mat4 d = gl_ModelViewMatrixInverseTranspose * gl_ProjectionMatrixInverseTranspose
           * gl_ModelViewProjectionMatrixInverseTranspose * gl_TextureMatrixInverseTranspose[0];
    vec3 n = gl_NormalMatrix * gl_Normal * gl_NormalScale;
    gl_Position = a * b * c * d * gl_Vertex + vec4(n, 0.0);
}
