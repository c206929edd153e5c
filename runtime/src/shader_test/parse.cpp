// Splitting a .shader_test file into its sections (docs/design/formats.md, shader_test).
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <string_view>

#include "arbiter/runtime/shader_test.h"
#include "shader_test/words.h"

namespace arbiter::runtime {
namespace {

enum class Section : uint8_t {
  None,
  Require,
  VertexProgram,
  FragmentProgram,
  VertexShader,
  FragmentShader,
  VertexPassthrough,
  VertexData,
  Test,
};

struct SectionName {
  std::string_view name;
  Section section;
};

constexpr std::array<SectionName, 8> kSections{{
    {"require", Section::Require},
    {"vertex program", Section::VertexProgram},
    {"fragment program", Section::FragmentProgram},
    {"vertex shader", Section::VertexShader},
    {"fragment shader", Section::FragmentShader},
    {"vertex shader passthrough", Section::VertexPassthrough},
    {"vertex data", Section::VertexData},
    {"test", Section::Test},
}};

ShaderTestSource* SourceOf(ShaderTest* test, Section section) {
  switch (section) {
    case Section::VertexProgram:
      return &test->vertex_program;
    case Section::FragmentProgram:
      return &test->fragment_program;
    case Section::VertexShader:
      return &test->vertex_shaders.back();
    case Section::FragmentShader:
      return &test->fragment_shaders.back();
    default:
      return nullptr;
  }
}

// A line of a line-oriented section: surrounding blanks and `#` comment lines dropped.
bool Meaningful(std::string_view line, std::string_view* out) {
  line = shader_test::Trim(line);
  if (line.empty() || line[0] == '#') return false;
  *out = line;
  return true;
}

}  // namespace

std::string_view TestStatusName(TestStatus status) {
  switch (status) {
    case TestStatus::Pass:
      return "PASS";
    case TestStatus::Fail:
      return "FAIL";
    case TestStatus::Skip:
      return "SKIP";
  }
  return "FAIL";
}

bool ParseShaderTest(std::string_view text, std::string path, ShaderTest* test, int* error_line,
                     std::string* error) {
  *test = ShaderTest{};
  test->path = std::move(path);
  Section section = Section::None;
  std::vector<bool> seen(kSections.size() + 1, false);
  int number = 0;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view raw = text.substr(pos, end - pos);
    pos = end + 1;
    ++number;
    if (!raw.empty() && raw.back() == '\r') raw.remove_suffix(1);
    std::string_view line = shader_test::Trim(raw);
    if (!line.empty() && line.front() == '[' && line.back() == ']') {
      std::string_view name = line.substr(1, line.size() - 2);
      section = Section::None;
      for (const SectionName& s : kSections) {
        if (s.name == name) section = s.section;
      }
      if (section == Section::None) {
        *error_line = number;
        *error = fmt::format("unknown section [{}]", name);
        return false;
      }
      const auto index = static_cast<size_t>(section);
      if (section == Section::VertexShader) test->vertex_shaders.emplace_back();
      if (section == Section::FragmentShader) test->fragment_shaders.emplace_back();
      const bool repeatable =
          section == Section::VertexShader || section == Section::FragmentShader;
      if (seen[index] && !repeatable) {
        *error_line = number;
        *error = fmt::format("section [{}] appears twice", name);
        return false;
      }
      seen[index] = true;
      if (ShaderTestSource* source = SourceOf(test, section)) source->line = number;
      if (section == Section::VertexPassthrough) {
        test->vertex_passthrough = true;
        test->passthrough_line = number;
      }
      continue;
    }
    std::string_view content;
    switch (section) {
      case Section::None:  // piglit ignores what precedes the first section (comments)
        break;
      case Section::Require:
        if (Meaningful(raw, &content)) test->require.push_back({number, std::string(content)});
        break;
      case Section::VertexData:
        if (Meaningful(raw, &content)) test->vertex_data.push_back({number, std::string(content)});
        break;
      case Section::Test:
        if (Meaningful(raw, &content)) test->commands.push_back({number, std::string(content)});
        break;
      case Section::VertexPassthrough:
        if (Meaningful(raw, &content)) {
          *error_line = number;
          *error = "[vertex shader passthrough] takes no text";
          return false;
        }
        break;
      default: {
        ShaderTestSource* source = SourceOf(test, section);
        source->text.append(raw);
        source->text.push_back('\n');
        break;
      }
    }
  }
  // A file with no section is no shader test (piglit's shader_runner reports a pass for it:
  // arbiter does not); one with neither a program nor a command has nothing to run.
  if (std::find(seen.begin(), seen.end(), true) == seen.end()) {
    *error_line = 1;
    *error =
        "not a shader test: no section such as [require], [vertex shader], [fragment program] "
        "or [test] (the format: docs/run.md)";
    return false;
  }
  const bool programs = !test->vertex_shaders.empty() || !test->fragment_shaders.empty() ||
                        test->vertex_program.line != 0 || test->fragment_program.line != 0 ||
                        test->vertex_passthrough;
  if (!programs && test->commands.empty()) {
    *error_line = 1;
    *error = "nothing to run: the test has no shader, no program and no [test] command";
    return false;
  }
  if (test->vertex_passthrough && !test->vertex_shaders.empty()) {
    *error_line = test->passthrough_line;
    *error = "[vertex shader passthrough] and [vertex shader] together";
    return false;
  }
  return true;
}

std::string ShaderTestVersionDirective(const ShaderTest& test) {
  // piglit's shader_runner gives a shader without #version the version its [require] asks
  // for ("GLSL >= 1.20" -> "#version 120"): 1.10 is every shader's default.
  for (const ShaderTestLine& r : test.require) {
    std::vector<std::string> w = shader_test::Words(r.text);
    if (w.size() == 3 && w[0] == "GLSL" && (w[1] == ">=" || w[1] == "==") && w[2] != "1.10") {
      std::string digits;
      for (char c : w[2]) {
        if (c != '.') digits += c;
      }
      if (digits.size() == 3) return "#version " + digits + "\n";
    }
  }
  return "";
}

}  // namespace arbiter::runtime
