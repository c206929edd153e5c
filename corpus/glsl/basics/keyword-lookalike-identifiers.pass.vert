// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.6 "The following are the keywords in the language, and cannot be used for any other purpose than that defined by this document" (identifiers that only contain a keyword are fine)
#version 110
float floatValue, in_, out0, inout_, uniform1, varyings, attributes, Const, form, iff, elsewhere;
float do_, done, forward, whilst, voids, booleans, truth, falsehood, discarded, returned, structure;
float mat2_, vec4x, ivec, bvec, sampler, sampler2, sampler2DShadows, intensity, mat, vec;
void main()
{
    gl_Position = vec4(floatValue);
}
