// Fuzz target: the GLSL translator, with the property "every program the checker accepts
// translates to output its target's validator accepts" as the oracle (as `arbiter translate`
// checks it). One target per input, picked by one of its bytes, so that a run costs what it
// did with GLSL 1.10 alone: glsl110 (arbiter's own GLSL check), glsl120, glsl330, es100,
// es300 (glslang) and vk450 (glslang, then spirv-val on the SPIR-V module). A refusal names a
// construct the target cannot express: not a translator bug.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "accept_arb.h"
#include "arbiter/arbvp/emit.h"
#include "arbiter/runtime/translate.h"
#include "arbiter/targets/targets.h"

namespace {

using namespace arbiter;

constexpr arbvp::EmitTarget kTargets[] = {arbvp::EmitTarget::Glsl110, arbvp::EmitTarget::Glsl120,
                                          arbvp::EmitTarget::Glsl330, arbvp::EmitTarget::Es100,
                                          arbvp::EmitTarget::Es300,   arbvp::EmitTarget::Vk450};
constexpr targets::GlslDialect kDialects[] = {
    targets::GlslDialect::Glsl110, targets::GlslDialect::Glsl120, targets::GlslDialect::Glsl330Core,
    targets::GlslDialect::Es100,   targets::GlslDialect::Es300,   targets::GlslDialect::Vulkan450};

[[noreturn]] void Fail(const char* target, const std::string& error, const std::string& program,
                       const std::string& translation) {
  std::fprintf(stderr,
               "fuzz_translate: an accepted program's translation to %s is not valid: %s\n"
               "---- program ----\n%s\n---- translation ----\n%s\n",
               target, error.c_str(), program.c_str(), translation.c_str());
  __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fuzz::AcceptedProgram accepted;
  if (!fuzz::AcceptArbProgram(data, size, &accepted)) return -1;
  const arbvp::Program* program = accepted.checked.program.get();
  const bool vertex = accepted.vertex;
  const compiler::SourceFile* source = accepted.source.get();
  const size_t pick = data[size / 2] % std::size(kTargets);
  arbvp::EmitOptions options;
  options.target = kTargets[pick];
  const std::string name(arbvp::EmitTargetName(options.target));
  if (options.target == arbvp::EmitTarget::Glsl110) {
    runtime::CheckedTranslation t =
        runtime::TranslateChecked(vertex ? program : nullptr, vertex ? nullptr : program, options,
                                  vertex ? source : nullptr, vertex ? nullptr : source);
    if (!t.ok && !t.refused)
      Fail("glsl110", t.error, source->text(), vertex ? t.vertex : t.fragment);
    return 0;
  }
  if (!arbvp::FindUntranslatable(*program, options).what.empty()) return 0;
  const arbvp::Translation t = arbvp::EmitGlsl(*program, options, source);
  const targets::Stage stage = vertex ? targets::Stage::Vertex : targets::Stage::Fragment;
  std::vector<targets::Message> messages;
  if (!targets::ValidateGlsl(t.glsl, stage, kDialects[pick], &messages)) {
    Fail(name.c_str(), messages.empty() ? "" : targets::FormatMessage(messages[0]), source->text(),
         t.glsl);
  }
  if (options.target == arbvp::EmitTarget::Vk450) {
    std::vector<uint32_t> spirv;
    if (!targets::CompileGlslToSpirv(t.glsl, stage, &spirv, &messages)) {
      Fail("spirv", messages.empty() ? "" : targets::FormatMessage(messages.back()), source->text(),
           t.glsl);
    }
  }
  return 0;
}
