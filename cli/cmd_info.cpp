// arbiter info: statistics and reflection of each input program, in text or JSON.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cstdio>
#include <nlohmann/json.hpp>

#include "arbiter/arbvp/check.h"
#include "arbiter/arbvp/reflect.h"
#include "cli.h"

namespace arbiter::cli {
namespace {

nlohmann::ordered_json ToJson(const std::string& path, const arbvp::Reflection& r) {
  nlohmann::ordered_json j;
  j["path"] = path;
  j["kind"] = r.kind;
  j["options"] = r.options;
  j["stats"] = {{"instructions", r.stats.instructions},
                {"alu_instructions", r.stats.alu_instructions},
                {"tex_instructions", r.stats.tex_instructions},
                {"tex_indirections", r.stats.tex_indirections},
                {"temporaries", r.stats.temporaries},
                {"parameters", r.stats.parameters},
                {"attributes", r.stats.attributes},
                {"address_registers", r.stats.address_registers},
                {"outputs", r.stats.outputs}};
  auto vars = [](const std::vector<arbvp::ReflectedVariable>& list) {
    nlohmann::ordered_json a = nlohmann::ordered_json::array();
    for (const auto& v : list) a.push_back({{"name", v.name}, {"bindings", v.bindings}});
    return a;
  };
  j["attributes"] = vars(r.attributes);
  j["parameters"] = vars(r.parameters);
  j["env"] = r.env_indices;
  j["local"] = r.local_indices;
  j["state"] = r.state;
  j["outputs_written"] = r.outputs_written;
  nlohmann::ordered_json tex = nlohmann::ordered_json::array();
  for (const auto& t : r.textures) tex.push_back({{"unit", t.unit}, {"target", t.target}});
  j["textures"] = tex;
  return j;
}

std::string ToText(const std::string& path, const arbvp::Reflection& r) {
  std::string out = fmt::format("{}: {} program\n", path, r.kind);
  if (!r.options.empty()) out += fmt::format("  options: {}\n", fmt::join(r.options, ", "));
  const arbvp::Stats& s = r.stats;
  if (r.kind == "fragment") {
    out += fmt::format("  instructions: {} (ALU {}, TEX {}), texture indirections: {}\n",
                       s.instructions, s.alu_instructions, s.tex_instructions, s.tex_indirections);
  } else {
    out += fmt::format("  instructions: {}\n", s.instructions);
  }

  out += fmt::format(
      "  temporaries: {}, parameters: {}, attributes: {}, address registers: {}, outputs: {}\n",
      s.temporaries, s.parameters, s.attributes, s.address_registers, s.outputs);
  auto vars = [&](std::string_view title, const std::vector<arbvp::ReflectedVariable>& list) {
    if (list.empty()) return;
    out += fmt::format("  {}:\n", title);
    for (const auto& v : list) {
      out += fmt::format("    {} = {}\n", v.name.empty() ? "(inline)" : v.name,
                         fmt::join(v.bindings, ", "));
    }
  };
  vars("attributes", r.attributes);
  vars("parameters", r.parameters);
  if (!r.env_indices.empty())
    out += fmt::format("  program.env: {}\n", fmt::join(r.env_indices, ", "));
  if (!r.local_indices.empty()) {
    out += fmt::format("  program.local: {}\n", fmt::join(r.local_indices, ", "));
  }
  if (!r.state.empty()) out += fmt::format("  state: {}\n", fmt::join(r.state, ", "));
  if (!r.outputs_written.empty()) {
    out += fmt::format("  outputs written: {}\n", fmt::join(r.outputs_written, ", "));
  }
  for (const auto& t : r.textures) out += fmt::format("  texture[{}]: {}\n", t.unit, t.target);
  return out;
}

}  // namespace

int RunInfo(const CommonOptions& options) {
  if (options.format == "sarif") {
    std::fputs("arbiter: error: info prints text or json; sarif is for diagnostics (check)\n",
               stderr);
    return static_cast<int>(Exit::Usage);
  }
  std::optional<compiler::LimitProfile> profile;
  std::optional<arbvp::ProgramKind> stage;
  if (!ResolveLimits(options, &profile) || !ResolveStage(options, &stage)) {
    return static_cast<int>(Exit::Usage);
  }
  arbvp::CheckOptions check_options;
  check_options.profile = profile ? &*profile : nullptr;
  check_options.expected_kind = stage;

  Exit exit = Exit::Ok;
  std::vector<compiler::FileReport> failed;
  std::vector<std::unique_ptr<compiler::SourceFile>> sources;
  nlohmann::ordered_json programs = nlohmann::ordered_json::array();
  std::string text;
  for (const Input& input : ExpandInputs(options.files)) {
    compiler::FileReport report;
    report.path = input.display_path;
    std::unique_ptr<compiler::SourceFile> source = ReadInput(input, &report);
    if (!source) {
      exit = Worse(exit, Exit::Environment);
      failed.push_back(std::move(report));
      continue;
    }
    compiler::DiagnosticSink sink;
    arbvp::CheckResult result = arbvp::CheckProgram(*source, check_options, &sink);
    if (!result.ok) {
      exit = Worse(exit, Exit::Rejected);
      report.diagnostics = std::move(sink.diagnostics());
      failed.push_back(std::move(report));
      sources.push_back(std::move(source));
      continue;
    }
    arbvp::Reflection reflection = arbvp::Reflect(*result.program, result.stats);
    programs.push_back(ToJson(input.display_path, reflection));
    text += ToText(input.display_path, reflection);
  }
  if (options.format == "json") {
    nlohmann::ordered_json doc;
    doc["programs"] = programs;
    std::fputs((doc.dump(2) + "\n").c_str(), stdout);
  } else {
    std::fputs(text.c_str(), stdout);
  }
  if (!failed.empty()) {
    CommonOptions diag_options = options;
    if (diag_options.format != "text") diag_options.format = "text";
    PrintReports(failed, diag_options);
  }
  return static_cast<int>(exit);
}

}  // namespace arbiter::cli
