// arbiter translate --target (translate_targets.h).
#include "translate_targets.h"

#include <fmt/format.h>

#include <cstring>
#include <vector>

#include "arbiter/targets/targets.h"

namespace arbiter::cli {
namespace {

using arbvp::EmitTarget;

constexpr OutputTarget kTargets[] = {
    {"glsl110", EmitTarget::Glsl110, OutputKind::Glsl, ""},
    {"glsl120", EmitTarget::Glsl120, OutputKind::Glsl, ""},
    {"glsl330", EmitTarget::Glsl330, OutputKind::Glsl, ""},
    {"es100", EmitTarget::Es100, OutputKind::Glsl, ""},
    {"es300", EmitTarget::Es300, OutputKind::Glsl, ""},
    {"vk450", EmitTarget::Vk450, OutputKind::Glsl, ""},
    {"spirv", EmitTarget::Vk450, OutputKind::Spirv, ".spv"},
    {"hlsl", EmitTarget::Vk450, OutputKind::Hlsl, ".hlsl"},
    {"msl", EmitTarget::Vk450, OutputKind::Msl, ".metal"},
};

// The validator's dialect of a GLSL target, by its --target spelling.
targets::GlslDialect Dialect(EmitTarget t) {
  return targets::GlslDialectNamed(EmitTargetName(t)).value_or(targets::GlslDialect::Glsl110);
}

std::string FirstError(const std::vector<targets::Message>& messages) {
  for (const targets::Message& m : messages) {
    if (m.severity == targets::Message::Severity::Error) return targets::FormatMessage(m);
  }
  return messages.empty() ? "no message" : targets::FormatMessage(messages.front());
}

// One stage's output from its GLSL: "" and *error set on a validator's refusal.
std::string Convert(const OutputTarget& target, const std::string& glsl, targets::Stage stage,
                    std::string* error) {
  std::vector<targets::Message> messages;
  const char* what = stage == targets::Stage::Vertex ? "vertex" : "fragment";
  if (target.kind == OutputKind::Glsl) {
    if (!targets::ValidateGlsl(glsl, stage, Dialect(target.dialect), &messages)) {
      *error = fmt::format("the {} {} shader does not compile: {}", target.name, what,
                           FirstError(messages));
    }
    return glsl;
  }
  std::vector<uint32_t> spirv;
  if (!targets::CompileGlslToSpirv(glsl, stage, &spirv, &messages)) {
    *error = fmt::format("the GLSL 4.50 {} shader does not compile to valid SPIR-V: {}", what,
                         FirstError(messages));
    return "";
  }
  if (target.kind == OutputKind::Spirv) {
    std::string bytes(spirv.size() * sizeof(uint32_t), '\0');
    std::memcpy(bytes.data(), spirv.data(), bytes.size());
    return bytes;
  }
  std::string text;
  if (target.kind == OutputKind::Hlsl) {
    if (!targets::SpirvToHlsl(spirv, &text, &messages)) {
      *error = fmt::format("SPIRV-Cross cannot write the {} shader as HLSL: {}", what,
                           FirstError(messages));
    } else if (!targets::ValidateHlsl(text, stage, &messages)) {
      *error = fmt::format("the HLSL {} shader does not compile: {}", what, FirstError(messages));
    }
    return text;
  }
  if (!targets::SpirvToMsl(spirv, &text, &messages)) {
    *error = fmt::format("SPIRV-Cross cannot write the {} shader as MSL: {}", what,
                         FirstError(messages));
  }
  return text;
}

// What HLSL (shader model 5.0) lacks beyond vk450's GLSL: Direct3D 11 has no point size, so
// a write of result.pointsize is refused (SPIRV-Cross cannot write it either).
arbvp::Untranslatable FindUntranslatableHlsl(const arbvp::Program& program) {
  for (const arbvp::Instruction& inst : program.instructions) {
    const int var = inst.dst.var;
    if (var < 0 || static_cast<size_t>(var) >= program.vars.size()) continue;
    for (const arbvp::Binding& b : program.vars[static_cast<size_t>(var)].bindings) {
      if (b.kind == arbvp::BindingKind::Result && b.result == arbvp::ResultReg::PointSize) {
        return {
            "result.pointsize: HLSL shader model 5.0 has no point size (Direct3D 11 draws "
            "points one pixel wide)",
            inst.dst.range};
      }
    }
  }
  return {};
}

}  // namespace

const OutputTarget* LookupOutputTarget(std::string_view name) {
  for (const OutputTarget& t : kTargets) {
    if (t.name == name) return &t;
  }
  return nullptr;
}

std::string OutputTargetNames() {
  std::string out;
  for (const OutputTarget& t : kTargets) {
    if (!out.empty()) out += ", ";
    out += t.name;
  }
  return out;
}

TargetTranslation TranslateForTarget(const OutputTarget& target, const arbvp::Program* vertex,
                                     const arbvp::Program* fragment,
                                     const arbvp::EmitOptions& options,
                                     const compiler::SourceFile* vertex_source,
                                     const compiler::SourceFile* fragment_source) {
  TargetTranslation out;
  arbvp::EmitOptions emit = options;
  emit.target = target.dialect;
  for (const auto& [program, source] :
       {std::pair{vertex, vertex_source}, {fragment, fragment_source}}) {
    if (!program) continue;
    arbvp::Untranslatable u = arbvp::FindUntranslatable(*program, emit);
    if (u.what.empty() && target.kind == OutputKind::Hlsl) u = FindUntranslatableHlsl(*program);
    if (u.what.empty()) continue;
    compiler::LineCol at = source ? source->Locate(u.range.begin) : compiler::LineCol{};
    out.error =
        fmt::format("{}:{}: error: {}; arbiter cannot translate this program to --target {}",
                    at.line, at.column, u.what, target.name);
    out.refused = true;
    return out;
  }
  std::string vs;
  std::string fs;
  if (vertex && fragment) {
    arbvp::PairTranslation pair =
        arbvp::EmitGlslPair(*vertex, *fragment, emit, vertex_source, fragment_source);
    vs = std::move(pair.vertex);
    fs = std::move(pair.fragment);
    out.bindings = std::move(pair.bindings);
  } else {
    const arbvp::Program* one = vertex ? vertex : fragment;
    arbvp::Translation t = arbvp::EmitGlsl(*one, emit, vertex ? vertex_source : fragment_source);
    (vertex ? vs : fs) = std::move(t.glsl);
    out.bindings = std::move(t.bindings);
  }
  if (!vs.empty()) out.vertex = Convert(target, vs, targets::Stage::Vertex, &out.error);
  if (out.error.empty() && !fs.empty()) {
    out.fragment = Convert(target, fs, targets::Stage::Fragment, &out.error);
  }
  out.ok = out.error.empty();
  return out;
}

}  // namespace arbiter::cli
