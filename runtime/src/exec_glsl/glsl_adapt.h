// Adapting the GLSL translation of ARB programs for readback (the mesa-glsl engine), the
// way program_rewrite.h adapts the ARB programs themselves: the translation's output
// built-ins become globals, its `main` becomes `arbiter_main`, and a generated `main` calls it
// and then copies the globals to colour attachments. A vertex shader alone sends them through
// varyings to a generated fragment shader; a fragment shader alone gets a generated vertex
// shader that feeds its inputs from generic attributes (exec::kFragmentInputAttribs).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "arbiter/runtime/translate.h"
#include "exec/program_rewrite.h"

namespace arbiter::runtime::exec {

// The text edits of the adaptation, shared with the target engines (target_adapt.h); they
// work on identifiers and lines only, never on the phrasing of statements.
using Renames = std::map<std::string, std::string>;
// Replaces every identifier of `text` found in `renames` (comments included: harmless).
std::string RenameIdentifiers(const std::string& text, const Renames& renames);
// Drops every line that contains `needle`.
std::string DropLines(const std::string& text, const std::string& needle);
// Inserts `globals` after the leading preprocessor and default-precision lines (#version and
// #extension must come before any declaration, ES precision before any float declaration).
std::string InsertGlobals(const std::string& text, const std::string& globals);
// The shader `text` with its `main` renamed `arbiter_main`, the identifiers of `renames`
// replaced and `globals` inserted (InsertGlobals); false when it has no `void main()`.
[[nodiscard]] bool AdaptMain(const std::string& text, const Renames& renames,
                             const std::string& globals, std::string* out, std::string* error);

// One draw of the GLSL engine: both shaders and what each attachment receives (an index into
// RunPlan::outputs, or kAliveFlag).
struct GlslPass {
  std::string vertex;
  std::string fragment;
  std::vector<int> attachments;
};

// The user attribute of the vertex shader that carries the point's clip position (bound to
// RunPlan::position_attrib), and the generated ones of a fragment shader alone.
inline constexpr const char* kPixelAttribute = "arbiter_pixel";
struct GeneratedAttribute {
  const char* name;
  int location;
};
std::vector<GeneratedAttribute> FragmentInputAttributes();

// Plans the passes for `plan` (from PlanRun on the same programs) and `translation`. False
// (with `error`) when the translation's text does not have the expected shape.
[[nodiscard]] bool PlanGlslPasses(const RunPlan& plan, const CheckedTranslation& translation,
                                  int max_attachments, std::vector<GlslPass>* passes,
                                  std::string* error);

}  // namespace arbiter::runtime::exec
