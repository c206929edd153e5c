// ARB_fragment_coord_conventions' redeclarations of gl_FragCoord in GLSL 1.10 and 1.20
// fragment shaders, judged by arbiter and hidden from glslang, which takes neither 'layout'
// nor a global 'in' for them before GLSL 1.50.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "arbiter/compiler/diagnostic.h"
#include "arbiter/compiler/source.h"
#include "arbiter/glsl/check.h"

namespace arbiter::glsl {

// Whether `id` is a layout qualifier identifier of the extension: origin_upper_left or
// pixel_center_integer, in any case (4.3.x: "these identifiers are not case-sensitive").
bool IsFragCoordLayoutId(std::string_view id);

// Judges every redeclaration of gl_FragCoord (`in vec4 gl_FragCoord;`, with or without
// `layout(origin_upper_left, pixel_center_integer)`) and every layout qualifier naming one of
// the extension's identifiers in `texts`, the shader's strings (their offsets are those of
// `files`, which name them in diagnostics), and blanks each judged one in `texts`, keeping
// lines and columns: what the extension forbids is reported into `sink`
// (glsl-fragcoord-redeclaration). `preamble` is what glslang reads first (prepare.h);
// `available`: the target has the extension. Only text the preprocessor compiles is judged
// (conditionals.h); where arbiter cannot tell, a valid redeclaration is blanked and nothing
// is reported.
void HideFragCoordRedeclarations(Stage stage, std::span<const compiler::SourceFile* const> files,
                                 std::string_view preamble, bool available,
                                 std::vector<std::string>* texts, compiler::DiagnosticSink* sink);

}  // namespace arbiter::glsl
