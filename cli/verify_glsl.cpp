// LoadGlslSubjects: see verify_glsl.h.
#include "verify_glsl.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "arbiter/runtime/shader_test.h"

namespace arbiter::cli {
namespace {

bool IsShaderTest(const std::string& path) { return path.ends_with(".shader_test"); }

// The named paths and, under directories, every GLSL shader and .shader_test (sorted).
std::vector<std::string> Expand(const std::vector<std::string>& args) {
  std::vector<std::string> out;
  for (const std::string& arg : args) {
    std::error_code ec;
    if (!std::filesystem::is_directory(arg, ec)) {
      if (IsVerifyGlslPath(arg)) out.push_back(arg);
      continue;
    }
    std::vector<std::string> found;
    for (auto it = std::filesystem::recursive_directory_iterator(arg, ec);
         !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec)) {
      if (it->is_regular_file(ec) && IsVerifyGlslPath(it->path().string())) {
        found.push_back(it->path().string());
      }
    }
    std::sort(found.begin(), found.end());
    out.insert(out.end(), found.begin(), found.end());
  }
  return out;
}

// One shader checked and reflected; null when arbiter's checker rejects it (with its
// diagnostics in `out->reports`, `*runnable` true) or it has nothing to run (a shader
// object without main(): `*runnable` false).
const glsl::Reflection* Reflect(glsl::Stage stage, const compiler::SourceFile* file,
                                LoadedGlsl* out, bool* runnable) {
  compiler::DiagnosticSink sink(20);
  auto r = std::make_unique<glsl::Reflection>(glsl::ReflectShader(stage, {file}, &sink));
  *runnable = r->ok || sink.error_count() > 0;
  if (!*runnable) return nullptr;
  if (!r->ok || sink.error_count() > 0) {
    compiler::FileReport report;
    report.path = file->path();
    report.diagnostics = std::move(sink.diagnostics());
    out->reports.push_back(std::move(report));
    return nullptr;
  }
  out->reflections.push_back(std::move(r));
  return out->reflections.back().get();
}

const compiler::SourceFile* Keep(std::string path, std::string text, LoadedGlsl* out) {
  out->files.push_back(std::make_unique<compiler::SourceFile>(std::move(path), std::move(text)));
  return out->files.back().get();
}

// Counts a shader that was not verified: rejected, or with nothing to run.
Exit Skip(bool rejected, LoadedGlsl* out) {
  ++(rejected ? out->rejected : out->skipped);
  return rejected ? Exit::Rejected : Exit::Ok;
}

// A .shader_test's shaders as one subject: each section's text after as many newlines as
// the test has lines before it, so that positions are the test file's.
Exit LoadShaderTest(const std::string& path, const std::string& text, LoadedGlsl* out) {
  runtime::ShaderTest test;
  int line = 0;
  std::string error;
  if (!runtime::ParseShaderTest(text, path, &test, &line, &error)) {
    fmt::print(stderr, "{}:{}: error: {}\n", path, line, error);
    ++out->rejected;
    return Exit::Rejected;
  }
  if (test.vertex_shaders.size() > 1 || test.fragment_shaders.size() > 1 ||
      (test.vertex_shaders.empty() && test.fragment_shaders.empty())) {
    ++out->skipped;
    return Exit::Ok;
  }
  runtime::GlslVerifySubject s;
  s.name = path;
  bool runnable = true;
  // A shader without #version gets the one [require] asks for, on its section's header line
  // (as `arbiter run` and piglit give it).
  const std::string version = runtime::ShaderTestVersionDirective(test);
  auto section = [&](const runtime::ShaderTestSource& src) {
    const bool add = src.text.find("#version") == std::string::npos && !version.empty();
    const auto pad = static_cast<size_t>(add && src.line > 0 ? src.line - 1 : src.line);
    return Keep(path, std::string(pad, '\n') + (add ? version : "") + src.text, out);
  };
  if (!test.vertex_shaders.empty()) {
    s.vertex = section(test.vertex_shaders[0]);
    s.vertex_reflection = Reflect(glsl::Stage::Vertex, s.vertex, out, &runnable);
    if (s.vertex_reflection == nullptr) return Skip(runnable, out);
  }
  if (!test.fragment_shaders.empty()) {
    s.fragment = section(test.fragment_shaders[0]);
    s.fragment_reflection = Reflect(glsl::Stage::Fragment, s.fragment, out, &runnable);
    if (s.fragment_reflection == nullptr) return Skip(runnable, out);
  }
  out->subjects.push_back(s);
  return Exit::Ok;
}

}  // namespace

bool IsVerifyGlslPath(const std::string& path) {
  return IsShaderTest(path) || glsl::StageFromPath(path).has_value();
}

Exit LoadGlslSubjects(const std::vector<std::string>& args, bool pair, LoadedGlsl* out) {
  Exit exit = Exit::Ok;
  runtime::GlslVerifySubject joined;
  for (const std::string& path : Expand(args)) {
    compiler::FileReport report;
    report.path = path;
    std::unique_ptr<compiler::SourceFile> read = ReadInput({path, path, {}, false, {}}, &report);
    if (!read) {
      out->reports.push_back(std::move(report));
      exit = Worse(exit, Exit::Environment);
      continue;
    }
    std::string text = read->text();
    if (IsShaderTest(path)) {
      exit = Worse(exit, LoadShaderTest(path, text, out));
      continue;
    }
    const glsl::Stage stage = *glsl::StageFromPath(path);
    const compiler::SourceFile* file = Keep(path, std::move(text), out);
    bool runnable = true;
    const glsl::Reflection* r = Reflect(stage, file, out, &runnable);
    if (r == nullptr) {
      exit = Worse(exit, Skip(runnable, out));
      continue;
    }
    runtime::GlslVerifySubject s;
    s.name = path;
    (stage == glsl::Stage::Vertex ? s.vertex : s.fragment) = file;
    (stage == glsl::Stage::Vertex ? s.vertex_reflection : s.fragment_reflection) = r;
    if (!pair) {
      out->subjects.push_back(s);
      continue;
    }
    if (stage == glsl::Stage::Vertex ? joined.vertex != nullptr : joined.fragment != nullptr) {
      return Exit::Usage;
    }
    if (s.vertex) {
      joined.vertex = s.vertex;
      joined.vertex_reflection = s.vertex_reflection;
    } else {
      joined.fragment = s.fragment;
      joined.fragment_reflection = s.fragment_reflection;
    }
    joined.name = joined.name.empty() ? path : joined.name + " + " + path;
  }
  if (pair && joined.vertex != nullptr && joined.fragment != nullptr) {
    out->subjects.push_back(joined);
  } else if (pair && (joined.vertex != nullptr || joined.fragment != nullptr)) {
    return Exit::Usage;
  }
  return exit;
}

}  // namespace arbiter::cli
