// The strictness layer: rules of GLSL 1.10 and 1.20 that glslang 12 does not enforce, one
// file per chapter (strict_<chapter>.cpp), run in a fixed order. A rule of 1.10 that 1.20
// drops checks ctx.version.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "../diag.h"
#include "../scan.h"
#include "../source_text.h"
#include "arbiter/compiler/diagnostic.h"
#include "arbiter/compiler/source.h"
#include "arbiter/glsl/check.h"

namespace glslang {
class TIntermediate;
struct TSourceLoc;
}  // namespace glslang

namespace arbiter::glsl {

struct FragmentOutputWrites {
  bool color = false;
  bool data = false;
  const compiler::SourceFile* data_file = nullptr;  // the first assignment to gl_FragData
  compiler::Range data_range;
};

struct StrictContext {
  Stage stage;
  int version;  // 110 or 120 (prepare.h)
  bool gpu4;    // EXT_gpu_shader4 or EXT_texture_array enabled: glslang parsed it as 1.30
  const std::vector<const compiler::SourceFile*>& sources;
  compiler::DiagnosticSink* sink;
  const glslang::TIntermediate& ast;  // the compiled shader
  bool link;                          // CheckOptions::link: judged as a program
  bool linked;                        // glslang's link step ran and succeeded
  // Whether the shader assigns gl_FragColor and gl_FragData (7.2): found in the whole AST by
  // CheckBuiltinVariables, judged after the link step by CheckFragmentOutputs.
  FragmentOutputWrites* fragment_writes;
  // What glslang reads before the shader's first line (-D, -U, --preamble; prepare.h).
  std::string_view preamble = {};
  // The functions glslang knows by another name (function_names.h), for RestoreSpelling.
  std::span<const Rename> renames = {};
  // Each source with its comments blanked, made once for the chapters that scan the text
  // (BlankedText); empty until the first asks.
  mutable std::vector<std::string> blanked = {};
  // Each source's tokens (Tokenize), made once for the rules that read tokens (SourceTokens).
  mutable std::vector<std::vector<Token>> tokens = {};
};

// Chapter 3.3, the preprocessor: #version below 110, #extension placement, #pragma
// optimize/debug inside functions, #line operands.
void CheckPreprocessor(const StrictContext& ctx);  // strict_preprocessor.cpp
// Chapter 3.3, #if and #elif: operands are integer literals and 'defined' only.
void CheckConditionals(const StrictContext& ctx);  // strict_conditionals.cpp
// Chapter 4, qualifiers: varying types, constant global initializers, the operands of const
// initializers glslang does not fold.
void CheckQualifiers(const StrictContext& ctx);  // strict_qualifiers.cpp
// Chapter 4.3.2: no function calls in const initializers.
void CheckConstInitializers(const StrictContext& ctx);  // strict_const.cpp
// Chapter 4.1.4: float literals beyond a 32-bit float (warnings).
void CheckFloatLiterals(const StrictContext& ctx);  // strict_numbers.cpp
// Chapters 4.1.9 and 4.3.3: array sizes are integral constant expressions, operand by operand.
void CheckArraySizes(const StrictContext& ctx);  // strict_arrays.cpp

// Chapter 5, operators and expressions: whole arrays as operands of '=', '==', '!=' and
// '?:'; an unparenthesized assignment as the third operand of '?:'.
void CheckExpressions(const StrictContext& ctx);  // strict_expressions.cpp
// Chapter 5.9: the operand of a unary '+' is a number (glslang drops the operator).
void CheckUnaryPlus(const StrictContext& ctx);  // strict_unary_plus.cpp

// Chapter 6.1, function definitions: out/inout arrays (1.10), samplers as out/inout parameters
// or return values, prototypes inside functions (1.20).
void CheckFunctions(const StrictContext& ctx);  // strict_functions.cpp

// Chapter 7, built-in variables: constant gl_TexCoord indices within gl_MaxTextureCoords;
// with the link step, not both gl_FragColor and gl_FragData assigned.
void CheckBuiltinVariables(const StrictContext& ctx);  // strict_builtins.cpp
// Chapter 7.1: a vertex shader must write gl_Position (checked when linking, as drivers do).
void CheckPositionWritten(const StrictContext& ctx);  // strict_builtins.cpp
// Chapter 7.2: not both gl_FragColor and gl_FragData assigned (a link error, as glslang's).
void CheckFragmentOutputs(const StrictContext& ctx);  // strict_builtins.cpp

// The whole-word occurrence of `name` on a line that also holds `keyword` (a declaration),
// in any source; false when there is none. For rules whose AST node has no usable location.
bool FindDeclaration(const StrictContext& ctx, std::string_view name, std::string_view keyword,
                     const compiler::SourceFile** file, compiler::Range* range);

// Tokenize of ctx.sources[index]'s text, computed once per shader; the tokens view the file.
const std::vector<Token>& SourceTokens(const StrictContext& ctx, size_t index);
// The same for a source given by its file (one of ctx.sources).
const std::vector<Token>& SourceTokens(const StrictContext& ctx, const compiler::SourceFile* file);

// BlankComments of ctx.sources[index], computed once per shader.
const std::string& BlankedText(const StrictContext& ctx, size_t index);

// The range of a glslang source location (line and column in string `loc.string`), `length`
// bytes long; false when the location is not in the sources.
bool RangeOfLoc(const StrictContext& ctx, const glslang::TSourceLoc& loc, size_t length,
                const compiler::SourceFile** file, compiler::Range* range);

// "GLSL 1.10" or "GLSL 1.20", for messages.
std::string_view VersionName(const StrictContext& ctx);

// Runs every chapter's checks on the AST of the whole shader, before glslang's link step
// removes the functions main() does not call.
void RunStrictChecks(const StrictContext& ctx);
// The checks that judge the linked shader.
void RunLinkStrictChecks(const StrictContext& ctx);

}  // namespace arbiter::glsl
