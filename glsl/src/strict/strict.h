// The GLSL 1.10 strictness layer: rules of the specification that glslang 12 does not
// enforce, one file per chapter (strict_<chapter>.cpp), run in a fixed order.
#pragma once

#include <string_view>
#include <vector>

#include "../diag.h"
#include "arbiter/compiler/diagnostic.h"
#include "arbiter/compiler/source.h"
#include "arbiter/glsl/check.h"

namespace glslang {
class TIntermediate;
}

namespace arbiter::glsl {

struct StrictContext {
  Stage stage;
  const std::vector<const compiler::SourceFile*>& sources;
  compiler::DiagnosticSink* sink;
  const glslang::TIntermediate& ast;  // the compiled shader
  bool linked;                        // the link step ran and succeeded
  bool as_program;                    // CheckOptions::link_as_program
};

// Chapter 3.3, the preprocessor: #version below 110, #extension placement, #pragma
// optimize/debug inside functions, #line operands.
void CheckPreprocessor(const StrictContext& ctx);  // strict_preprocessor.cpp
// Chapter 4, qualifiers: varying types, constant global initializers.
void CheckQualifiers(const StrictContext& ctx);  // strict_qualifiers.cpp
// Chapter 4.3.2: no function calls in const initializers.
void CheckConstInitializers(const StrictContext& ctx);  // strict_const.cpp

// Chapter 7, built-in variables: a vertex shader must write gl_Position (checked when
// linking, as drivers do).
void CheckBuiltinVariables(const StrictContext& ctx);  // strict_builtins.cpp

// The whole-word occurrence of `name` on a line that also holds `keyword` (a declaration),
// in any source; false when there is none. For rules whose AST node has no usable location.
bool FindDeclaration(const StrictContext& ctx, std::string_view name, std::string_view keyword,
                     const compiler::SourceFile** file, compiler::Range* range);

// Runs every chapter's checks.
void RunStrictChecks(const StrictContext& ctx);

}  // namespace arbiter::glsl
