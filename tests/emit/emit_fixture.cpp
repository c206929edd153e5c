// Shared helpers of the emitter tests.
#include "emit_fixture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "arbiter/glsl/check.h"

namespace arbiter::arbvp::testing {

namespace fs = std::filesystem;

std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string Render(const compiler::DiagnosticSink& sink) {
  std::string out;
  for (const compiler::Diagnostic& d : sink.diagnostics()) {
    if (d.severity != compiler::Severity::Error) continue;
    out += std::string(d.info->code) + ": " + d.message + "\n";
  }
  return out;
}

Checked CheckText(const std::string& name, const std::string& text) {
  Checked c;
  c.source = std::make_unique<compiler::SourceFile>(name, text);
  compiler::DiagnosticSink sink(0);
  CheckResult r = CheckProgram(*c.source, CheckOptions{}, &sink);
  if (r.ok) c.program = std::move(r.program);
  c.errors = Render(sink);
  return c;
}

Translation TranslateText(const std::string& text, const EmitOptions& options) {
  Checked c = CheckText("test", text);
  EXPECT_TRUE(c.program) << c.errors;
  if (!c.program) return {};
  return EmitGlsl(*c.program, options, c.source.get());
}

std::string GlslErrors(ProgramKind stage, const std::string& glsl) {
  bool vertex = stage == ProgramKind::Vertex;
  compiler::SourceFile file(vertex ? "translation.vert" : "translation.frag", glsl);
  compiler::DiagnosticSink sink(0);
  glsl::CheckOptions options;
  options.link = true;
  glsl::CheckResult r = glsl::CheckShader(vertex ? glsl::Stage::Vertex : glsl::Stage::Fragment,
                                          {&file}, options, &sink);
  std::string errors = Render(sink);
  if (!r.ok && errors.empty()) errors = "rejected without an error message";
  return errors;
}

std::vector<std::string> Statements(const std::string& glsl) {
  std::vector<std::string> out;
  size_t main = glsl.find("void main() {");
  if (main == std::string::npos) return out;
  std::istringstream in(glsl.substr(main));
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    size_t start = line.find_first_not_of(' ');
    if (start == std::string::npos) continue;
    line = line.substr(start);
    if (line.rfind("//", 0) == 0 || line == "}") continue;
    // Locals: the variables and the NV machine state.
    if (line.rfind("vec4 ", 0) == 0 || line.rfind("int ", 0) == 0 || line.rfind("ivec", 0) == 0 ||
        line.rfind("bvec4 ", 0) == 0) {
      continue;
    }
    if (line.find("// result.position is never written") != std::string::npos) continue;
    out.push_back(line);
  }
  return out;
}

std::vector<std::string> ValidCorpusFiles() {
  std::vector<std::string> files;
  fs::path root = fs::path(ARBITER_SOURCE_DIR) / "corpus" / "arb" / "valid";
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    std::string ext = entry.path().extension().string();
    if (entry.is_regular_file() &&
        (ext == ".vp" || ext == ".fp" || ext == ".arbvp" || ext == ".arbfp")) {
      files.push_back(fs::relative(entry.path(), root.parent_path()).generic_string());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace arbiter::arbvp::testing
