// arbiter link: GLSL shader objects of one or both stages checked as one program.
#include <fmt/format.h>

#include <functional>
#include <memory>

#include "arbiter/glsl/link.h"
#include "cli.h"
#include "options.h"

namespace arbiter::cli {
namespace {

struct LinkCommandOptions {
  CommonOptions common;            // --format --color --limits --error-limit -Werror
  std::vector<std::string> files;  // VERT FRAG, stages from their extensions
  std::vector<std::string> vert;   // --vert: the vertex shader's strings, in order
  std::vector<std::string> frag;   // --frag: the fragment shader's strings, in order
};

Input MakeInput(const std::string& path) {
  return {path, path == "-" ? "<stdin>" : path, {}, false, {}};
}

// Reads a stage's inputs, one report per file.
void ReadStage(const std::vector<Input>& inputs, std::vector<const compiler::SourceFile*>* sources,
               std::vector<std::unique_ptr<compiler::SourceFile>>* keep,
               std::vector<compiler::FileReport>* reports, Exit* exit) {
  for (const Input& input : inputs) {
    compiler::FileReport report;
    report.path = input.display_path;
    std::unique_ptr<compiler::SourceFile> source = ReadInput(input, &report);
    if (source) {
      sources->push_back(source.get());
      keep->push_back(std::move(source));
    } else {
      *exit = Exit::Environment;
    }
    reports->push_back(std::move(report));
  }
}

int RunLink(const LinkCommandOptions& options) {
  const CommonOptions& common = options.common;
  GlslSetup glsl_setup;
  if (std::optional<Exit> failed = ResolveGlslSetup(common, &glsl_setup)) {
    return static_cast<int>(*failed);
  }
  // Each named file is one shader object; --vert and --frag give one object of many strings.
  struct Object {
    glsl::Stage stage;
    std::vector<Input> strings;
  };
  std::vector<Object> objects;
  if (!options.vert.empty()) objects.push_back({glsl::Stage::Vertex, {}});
  for (const std::string& path : options.vert) objects.back().strings.push_back(MakeInput(path));
  if (!options.frag.empty()) objects.push_back({glsl::Stage::Fragment, {}});
  for (const std::string& path : options.frag) objects.back().strings.push_back(MakeInput(path));
  for (const std::string& path : options.files) {
    std::optional<glsl::Stage> stage = glsl::StageFromPath(path);
    if (!stage) {
      fmt::print(stderr,
                 "arbiter: error: cannot tell the stage of '{}' from its name (.vert .vs .vsh "
                 ".vert.glsl, .frag .fs .fsh .frag.glsl); name it with --vert FILE or --frag "
                 "FILE\n",
                 path);
      return static_cast<int>(Exit::Usage);
    }
    objects.push_back({*stage, {MakeInput(path)}});
  }
  if (objects.empty()) {
    fmt::print(stderr,
               "arbiter: error: link needs shaders: VERT FRAG, any shader objects of one or both "
               "stages, or --vert FILE... --frag FILE...\n");
    return static_cast<int>(Exit::Usage);
  }

  Exit exit = Exit::Ok;
  std::vector<compiler::FileReport> reports;
  std::vector<std::unique_ptr<compiler::SourceFile>> keep;
  std::vector<glsl::ShaderObject> shader_objects;
  for (const Object& object : objects) {
    shader_objects.push_back({object.stage, {}});
    ReadStage(object.strings, &shader_objects.back().strings, &keep, &reports, &exit);
  }
  if (exit == Exit::Ok) exit = LinkAndReport(shader_objects, common, glsl_setup, keep, &reports);
  PrintReports(reports, common);
  return static_cast<int>(exit);
}

}  // namespace

// Adds the `link` subcommand to `app`; the returned function runs it once it is parsed.
// (Declared in main.cpp, which registers the verbs.)
std::function<int()> AddLinkCommand(CLI::App* app) {
  auto options = std::make_shared<LinkCommandOptions>();
  CLI::App* link =
      app->add_subcommand("link", "check GLSL shaders (vertex, fragment or both) as one program");
  link->add_option("files", options->files,
                   "shader objects of one or both stages, each file one object, stages from "
                   "their names (.vert .vs .vsh .frag .fs .fsh, .vert.glsl .frag.glsl; '-' "
                   "needs --vert or --frag)");
  link->add_option("--vert", options->vert, "the vertex shader's files, in order (one shader)");
  link->add_option("--frag", options->frag, "the fragment shader's files, in order (one shader)");
  CommonOptions& common = options->common;
  AddFormatOption(link, &common.format, {"text", "json", "sarif"});
  AddColorOption(link, &common.color);
  AddLimitsOption(link, &common.limits);
  AddErrorLimitOption(link, &common.error_limit);
  AddWerrorFlag(link, &common.werror);
  AddGlslOptions(link, &common);
  return [options] { return RunLink(*options); };
}

}  // namespace arbiter::cli
