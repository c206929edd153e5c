// Translating ARB programs to GLSL 1.10 with a self-check: every translation is compiled
// (and, for a pair, linked) by glslang before anyone sees it, so a translator bug surfaces
// as an internal error, never as a silently wrong file.
#pragma once

#include <string>

#include "arbiter/arbvp/emit.h"
#include "arbiter/arbvp/ir.h"
#include "arbiter/compiler/source.h"

namespace arbiter::runtime {

struct CheckedTranslation {
  bool ok = false;
  std::string vertex;    // the vertex shader (empty when only a fragment program was given)
  std::string fragment;  // the fragment shader (empty when only a vertex program was given)
  arbvp::BindingMap bindings;
  // When !ok: what glslang said about the translation, lower case, with the shader text's
  // line ("the GLSL vertex shader does not compile: 12:5: 'x' : undeclared identifier").
  std::string error;
  // When !ok because the program uses a construct GLSL 1.10 cannot express (error names it,
  // with its position): a refusal, not a translator bug.
  bool refused = false;
};

// Translates a vertex program, a fragment program, or both as a pair (either may be null,
// not both; each checked without errors), and checks the result with glslang.
CheckedTranslation TranslateChecked(const arbvp::Program* vertex, const arbvp::Program* fragment,
                                    const arbvp::EmitOptions& options,
                                    const compiler::SourceFile* vertex_source,
                                    const compiler::SourceFile* fragment_source);

// TranslateChecked's two halves, for callers that reuse a verdict for the same text: the
// emitter's output (ok false; error set only when there is nothing to translate), and
// glslang's verdict on it (sets ok, or error).
CheckedTranslation EmitTranslation(const arbvp::Program* vertex, const arbvp::Program* fragment,
                                   const arbvp::EmitOptions& options,
                                   const compiler::SourceFile* vertex_source,
                                   const compiler::SourceFile* fragment_source);
void SelfCheckTranslation(CheckedTranslation* translation);

}  // namespace arbiter::runtime
