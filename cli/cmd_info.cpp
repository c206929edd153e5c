// arbiter info: statistics and reflection of each input program (ARB) or shader (GLSL), in
// text or JSON.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cstdio>
#include <nlohmann/json.hpp>

#include "arbiter/arbvp/check.h"
#include "arbiter/arbvp/reflect.h"
#include "arbiter/glsl/reflect.h"
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

// ---- GLSL shaders ----

std::vector<std::string> BuiltinNames(const std::vector<glsl::BuiltinUse>& list) {
  std::vector<std::string> names;
  names.reserve(list.size());
  for (const glsl::BuiltinUse& b : list) names.push_back(b.name);
  return names;
}

nlohmann::ordered_json ToJson(const std::vector<std::string>& paths, const glsl::Reflection& r) {
  nlohmann::ordered_json j;
  j["path"] = paths.front();
  if (paths.size() > 1) j["strings"] = paths;
  j["language"] = "glsl";
  j["stage"] = glsl::StageName(r.stage);
  j["resources"] = {{"uniform_components", r.resources.uniform_components},
                    {"varying_floats", r.resources.varying_floats},
                    {"vertex_attribs", r.resources.vertex_attribs},
                    {"samplers", r.resources.samplers}};
  auto vars = [](const std::vector<glsl::ReflectedVariable>& list, bool varying, bool sampler) {
    nlohmann::ordered_json a = nlohmann::ordered_json::array();
    for (const glsl::ReflectedVariable& v : list) {
      nlohmann::ordered_json o = {{"name", v.name}, {"type", v.type}, {"array_size", v.array_size}};
      if (varying) {
        o["read"] = v.read;
        o["written"] = v.written;
      } else {
        o["used"] = v.read;
      }
      if (sampler) o["lookups"] = v.lookups;
      a.push_back(o);
    }
    return a;
  };
  j["attributes"] = vars(r.attributes, false, false);
  j["uniforms"] = vars(r.uniforms, false, false);
  j["samplers"] = vars(r.samplers, false, true);
  j["varyings"] = vars(r.varyings, true, false);
  j["builtins_read"] = BuiltinNames(r.builtins_read);
  j["builtins_written"] = BuiltinNames(r.builtins_written);
  return j;
}

std::string ToText(const std::string& path, const glsl::Reflection& r) {
  std::string out = fmt::format("{}: {} shader\n", path, glsl::StageName(r.stage));
  const glsl::ResourceUse& use = r.resources;
  out += fmt::format("  uniform components: {}, varying floats: {}", use.uniform_components,
                     use.varying_floats);
  if (r.stage == glsl::Stage::Vertex) {
    out += fmt::format(", vertex attributes: {}", use.vertex_attribs);
  }
  out += fmt::format(", samplers: {}\n", use.samplers);
  auto vars = [&](std::string_view title, const std::vector<glsl::ReflectedVariable>& list,
                  bool varying) {
    if (list.empty()) return;
    out += fmt::format("  {}:\n", title);
    for (const glsl::ReflectedVariable& v : list) {
      out += fmt::format("    {} {}", v.type, v.name);
      if (v.array_size > 0) out += fmt::format("[{}]", v.array_size);
      if (!v.lookups.empty()) out += fmt::format(": {}", fmt::join(v.lookups, ", "));
      std::vector<std::string_view> flags;
      if (varying && v.written) flags.push_back("written");
      if (varying && v.read) flags.push_back("read");
      if (!v.read && !v.written) flags.push_back("unused");
      if (!flags.empty()) out += fmt::format(" ({})", fmt::join(flags, ", "));
      out += "\n";
    }
  };
  vars("attributes", r.attributes, false);
  vars("uniforms", r.uniforms, false);
  vars("samplers", r.samplers, false);
  vars("varyings", r.varyings, true);
  if (!r.builtins_read.empty()) {
    out += fmt::format("  built-ins read: {}\n", fmt::join(BuiltinNames(r.builtins_read), ", "));
  }
  if (!r.builtins_written.empty()) {
    out +=
        fmt::format("  built-ins written: {}\n", fmt::join(BuiltinNames(r.builtins_written), ", "));
  }
  return out;
}

// What info prints, gathered input by input.
struct InfoOutput {
  Exit exit = Exit::Ok;
  std::vector<compiler::FileReport> failed;
  std::vector<std::unique_ptr<compiler::SourceFile>> sources;
  nlohmann::ordered_json programs = nlohmann::ordered_json::array();
  std::string text;
};

// Reflects the inputs as one GLSL shader of `stage` (several files: its strings, in order).
void InfoShader(glsl::Stage stage, const std::vector<Input>& inputs,
                const glsl::CheckOptions& glsl_check, InfoOutput* out) {
  compiler::FileReport report;
  report.path = inputs.front().display_path;
  std::vector<const compiler::SourceFile*> strings;
  std::vector<std::string> paths;
  for (const Input& input : inputs) {
    std::unique_ptr<compiler::SourceFile> source = ReadInput(input, &report);
    if (!source) continue;
    strings.push_back(source.get());
    paths.push_back(input.display_path);
    out->sources.push_back(std::move(source));
  }
  if (strings.size() != inputs.size()) {
    out->exit = Worse(out->exit, Exit::Environment);
    out->failed.push_back(std::move(report));
    return;
  }
  compiler::DiagnosticSink sink;
  glsl::Reflection reflection = glsl::ReflectShader(stage, strings, &sink, glsl_check);
  if (!reflection.ok) {
    out->exit = Worse(out->exit, Exit::Rejected);
    report.diagnostics = std::move(sink.diagnostics());
    out->failed.push_back(std::move(report));
    return;
  }
  out->programs.push_back(ToJson(paths, reflection));
  out->text += ToText(paths.front(), reflection);
}

}  // namespace

int RunInfo(const CommonOptions& options) {
  GlslSetup glsl_setup;
  if (std::optional<Exit> failed = ResolveGlslSetup(options, &glsl_setup)) {
    return static_cast<int>(*failed);
  }
  const std::optional<compiler::LimitProfile>& profile = glsl_setup.profile;
  std::optional<arbvp::ProgramKind> stage;
  if (!ResolveStage(options, &stage)) return static_cast<int>(Exit::Usage);
  arbvp::CheckOptions check_options;
  check_options.profile = profile ? &*profile : nullptr;
  check_options.expected_kind = stage;

  InfoOutput out;
  std::vector<Input> inputs = ExpandInputs(options.files, ResolveJobs(options));
  if (options.stage == "vert" || options.stage == "frag") {
    // The files are the strings of one shader, as for check.
    if (!inputs.empty()) {
      InfoShader(options.stage == "vert" ? glsl::Stage::Vertex : glsl::Stage::Fragment, inputs,
                 glsl_setup.check, &out);
    }
    inputs.clear();
  }
  for (const Input& input : inputs) {
    if (std::optional<glsl::Stage> glsl_stage = GlslStage(options, input)) {
      InfoShader(*glsl_stage, {input}, glsl_setup.check, &out);
      continue;
    }
    compiler::FileReport report;
    report.path = input.display_path;
    std::unique_ptr<compiler::SourceFile> source = ReadInput(input, &report);
    if (!source) {
      out.exit = Worse(out.exit, Exit::Environment);
      out.failed.push_back(std::move(report));
      continue;
    }
    compiler::DiagnosticSink sink;
    arbvp::CheckResult result = arbvp::CheckProgram(*source, check_options, &sink);
    if (!result.ok) {
      out.exit = Worse(out.exit, Exit::Rejected);
      report.diagnostics = std::move(sink.diagnostics());
      out.failed.push_back(std::move(report));
      out.sources.push_back(std::move(source));
      continue;
    }
    arbvp::Reflection reflection = arbvp::Reflect(*result.program, result.stats);
    out.programs.push_back(ToJson(input.display_path, reflection));
    out.text += ToText(input.display_path, reflection);
  }
  if (options.format == "json") {
    nlohmann::ordered_json doc;
    doc["programs"] = out.programs;
    doc["diagnostics"] = DiagnosticsJson(out.failed);
    // A path that is not UTF-8 becomes U+FFFD instead of throwing.
    const std::string text =
        doc.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
    std::fputs((text + "\n").c_str(), stdout);
  } else {
    std::fputs(out.text.c_str(), stdout);
  }
  if (!out.failed.empty() && options.format != "json") {
    CommonOptions diag_options = options;
    if (diag_options.format != "text") diag_options.format = "text";
    PrintReports(out.failed, diag_options);
  }
  return static_cast<int>(out.exit);
}

}  // namespace arbiter::cli
