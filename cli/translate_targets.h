// arbiter translate --target: the dialects other than GLSL 1.10's built-in state, each output
// checked by its validator (targets/: glslang for GLSL and HLSL, spirv-val for SPIR-V).
#pragma once

#include <string>
#include <string_view>

#include "arbiter/arbvp/emit.h"
#include "arbiter/compiler/source.h"

namespace arbiter::cli {

// The --target values: the GLSL dialects, and spirv, hlsl, msl made from vk450's GLSL.
enum class OutputKind { Glsl, Spirv, Hlsl, Msl };
struct OutputTarget {
  std::string_view name;  // "es300"
  arbvp::EmitTarget dialect;
  OutputKind kind;
  std::string_view extension;  // appended to .vert/.frag ("" for GLSL, ".spv", ...)
};
// Null for an unknown name.
const OutputTarget* LookupOutputTarget(std::string_view name);
// "glsl110, glsl120, ..." for the usage text.
std::string OutputTargetNames();

struct TargetTranslation {
  bool ok = false;
  bool refused = false;  // a construct the target cannot express: error names it
  std::string error;
  std::string vertex;    // text, or the SPIR-V module's bytes
  std::string fragment;  // (empty when the job has no such program)
  arbvp::BindingMap bindings;
};

// Translates a vertex program, a fragment program, or both as a pair, for `target`, and holds
// every output to its validator (a failure is a translator bug: ok false, refused false).
TargetTranslation TranslateForTarget(const OutputTarget& target, const arbvp::Program* vertex,
                                     const arbvp::Program* fragment,
                                     const arbvp::EmitOptions& options,
                                     const compiler::SourceFile* vertex_source,
                                     const compiler::SourceFile* fragment_source);

}  // namespace arbiter::cli
