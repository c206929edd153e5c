// arbiter check: validate every input (ARB programs and GLSL shaders) and report its
// diagnostics, in input order whatever the number of worker threads.
#include <fmt/format.h>

#include "arbiter/arbvp/check.h"
#include "arbiter/glsl/check.h"
#include "arbiter/glsl/link.h"
#include "cli.h"
#include "driver_check.h"

namespace arbiter::cli {
namespace {

// One input's outcome; `source` stays alive until rendering (diagnostics point into it).
struct Checked {
  compiler::FileReport report;
  std::unique_ptr<compiler::SourceFile> source;
  std::vector<std::unique_ptr<compiler::SourceFile>> included;  // files #include read
  Exit exit = Exit::Ok;
  std::string text;  // the report rendered as text, when that is the format
};

// A .glsl file names no stage: --stage must.
const compiler::DiagnosticInfo kGlslStageUnknown{
    "glsl-stage-unknown", compiler::Severity::Error,
    "a .glsl file whose name does not say its stage and no --stage", ""};

Checked CheckOne(const Input& input, const CommonOptions& options,
                 const arbvp::CheckOptions& arb_options, const GlslSetup& glsl_setup) {
  Checked out;
  out.report.path = input.display_path;
  out.source = ReadInput(input, &out.report);
  if (!out.source) {
    out.exit = Exit::Environment;
    return out;
  }
  compiler::DiagnosticSink sink(options.error_limit);
  if (std::optional<glsl::Stage> stage = GlslStage(options, input)) {
    out.included = glsl::CheckShader(*stage, {out.source.get()}, glsl_setup.check, &sink).included;
  } else if (options.stage.empty() && glsl::IsGlslPath(input.path)) {
    sink.Report(kGlslStageUnknown, nullptr, {0, 0},
                fmt::format("cannot tell the stage of '{}': name it NAME.vert.glsl or "
                            "NAME.frag.glsl (or .vert, .frag, .vsh, .fsh), or give --stage "
                            "vert|frag",
                            input.display_path));
  } else {
    arbvp::CheckProgram(*out.source, arb_options, &sink);
  }
  sink.ApplyWarningPolicy(glsl_setup.warnings);
  if (sink.error_count() > 0) out.exit = Exit::Rejected;
  out.report.diagnostics = std::move(sink.diagnostics());
  out.report.dropped_errors = sink.dropped();
  // --driver-check: Mesa's verdict beside arbiter's (cli/driver_check.cpp).
  if (options.driver_check) {
    if (std::optional<glsl::Stage> stage = GlslStage(options, input)) {
      out.exit = Worse(out.exit, DriverCheck(options, *stage, {out.source.get()}, &out.report));
    }
  }
  return out;
}

// With --stage vert|frag the files are the strings of one shader, in order.
Checked CheckOneShader(const std::vector<Input>& inputs, const CommonOptions& options,
                       const GlslSetup& glsl_setup,
                       std::vector<std::unique_ptr<compiler::SourceFile>>* keep) {
  Checked out;
  std::vector<const compiler::SourceFile*> strings;
  for (const Input& input : inputs) {
    std::unique_ptr<compiler::SourceFile> source = ReadInput(input, &out.report);
    if (!source) {
      out.exit = Exit::Environment;
      continue;
    }
    strings.push_back(source.get());
    keep->push_back(std::move(source));
  }
  out.report.path = inputs.empty() ? "" : inputs.front().display_path;
  if (strings.size() != inputs.size()) return out;
  compiler::DiagnosticSink sink(options.error_limit);
  glsl::CheckOptions check = glsl_setup.check;
  check.link = options.link;
  out.included =
      glsl::CheckShader(options.stage == "vert" ? glsl::Stage::Vertex : glsl::Stage::Fragment,
                        strings, check, &sink)
          .included;
  sink.ApplyWarningPolicy(glsl_setup.warnings);
  if (sink.error_count() > 0) out.exit = Exit::Rejected;
  out.report.diagnostics = std::move(sink.diagnostics());
  out.report.dropped_errors = sink.dropped();
  // --driver-check: Mesa's verdict beside arbiter's (cli/driver_check.cpp).
  if (options.driver_check) {
    glsl::Stage stage = options.stage == "vert" ? glsl::Stage::Vertex : glsl::Stage::Fragment;
    out.exit = Worse(out.exit, DriverCheck(options, stage, strings, &out.report));
  }
  return out;
}

// --link: the GLSL files are the shader objects of one program (each file one object, its
// stage from its name). Diagnostics go to the report of the file they are in.
int CheckProgram(const std::vector<Input>& inputs, const CommonOptions& options,
                 const GlslSetup& glsl_setup) {
  Exit exit = Exit::Ok;
  std::vector<compiler::FileReport> reports;
  std::vector<std::unique_ptr<compiler::SourceFile>> keep;
  std::vector<glsl::ShaderObject> objects;
  for (const Input& input : inputs) {
    compiler::FileReport report;
    report.path = input.display_path;
    std::optional<glsl::Stage> stage = GlslStage(options, input);
    std::unique_ptr<compiler::SourceFile> source = ReadInput(input, &report);
    if (!source) {
      exit = Exit::Environment;
    } else if (!stage) {
      fmt::print(stderr,
                 "arbiter: error: --link: cannot tell the GLSL stage of '{}' from its name "
                 "(.vert .vs .vsh .vert.glsl, .frag .fs .fsh .frag.glsl)\n",
                 input.display_path);
      return static_cast<int>(Exit::Usage);
    } else {
      objects.push_back({*stage, {source.get()}});
    }
    keep.push_back(std::move(source));
    reports.push_back(std::move(report));
  }
  if (exit == Exit::Ok && !objects.empty()) {
    exit = LinkAndReport(objects, options, glsl_setup, keep, &reports);
  }
  PrintReports(reports, options);
  return static_cast<int>(exit);
}

}  // namespace

int RunCheck(const CommonOptions& options) {
  KeepMallocMemory();
  GlslSetup glsl_setup;
  if (std::optional<Exit> failed = ResolveGlslSetup(options, &glsl_setup)) {
    return static_cast<int>(*failed);
  }
  const std::optional<compiler::LimitProfile>& profile = glsl_setup.profile;
  std::optional<arbvp::ProgramKind> stage;
  if (!ResolveStage(options, &stage)) return static_cast<int>(Exit::Usage);
  arbvp::CheckOptions arb_options;
  arb_options.profile = profile ? &*profile : nullptr;
  arb_options.expected_kind = stage;

  std::vector<Input> inputs = ExpandInputs(options.files, ResolveJobs(options));
  std::vector<Checked> results;
  std::vector<std::unique_ptr<compiler::SourceFile>> strings;
  if (options.stage == "vert" || options.stage == "frag") {
    results.push_back(CheckOneShader(inputs, options, glsl_setup, &strings));
  } else if (options.link) {
    return CheckProgram(inputs, options, glsl_setup);
  } else {
    results.resize(inputs.size());
    // Text is rendered by the workers too: on one thread it was a tenth of an ARB batch.
    const bool text = options.format == "text";
    const compiler::TextOptions text_options = TextOptionsFor(options);
    ParallelFor(inputs.size(), ResolveJobs(options), [&](size_t i) {
      Checked checked = CheckOne(inputs[i], options, arb_options, glsl_setup);
      if (text) {
        // Rendered, the report and its source are freed here, in parallel, not at the end.
        results[i].text = compiler::RenderText(checked.report, text_options);
        results[i].exit = checked.exit;
      } else {
        results[i] = std::move(checked);
      }
    });
    if (text) {
      Exit exit = Exit::Ok;
      std::vector<std::string> rendered;
      rendered.reserve(results.size());
      for (Checked& c : results) {
        exit = Worse(exit, c.exit);
        rendered.push_back(std::move(c.text));
      }
      PrintText(rendered);
      return static_cast<int>(exit);
    }
  }
  Exit exit = Exit::Ok;
  std::vector<compiler::FileReport> reports;
  for (Checked& c : results) {
    exit = Worse(exit, c.exit);
    reports.push_back(std::move(c.report));
  }
  PrintReports(reports, options);
  return static_cast<int>(exit);
}

}  // namespace arbiter::cli
