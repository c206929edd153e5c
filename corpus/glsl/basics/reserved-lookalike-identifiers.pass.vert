// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.6 "The following are the keywords reserved for future use. Using them will result in an error" (identifiers that only contain a reserved word are fine)
#version 110
float asm_, classes, unions, enumerate, typedefs, templates, thisOne, packed1, gotoLabel;
float switch_, defaults, inlined, noinline_, volatility, publicValue, statics, externs;
float externally, interfaces, longer, shorter, doubled, halfway, fixedPoint, unsignedValue;
float inputs, outputs, hvec, dvec5, fvec, sampler2DRects, sizeOf, casts, namespaces, usingValue;
float Double, Half, Switch, Long;
void main()
{
    gl_Position = vec4(asm_);
}
