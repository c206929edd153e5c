// docs/diagnostics.md is generated from the diagnostic tables (arbvp/src/diagnostics.def,
// glsl/src/diagnostics.def) and the command line's own codes: every code, its severity, summary
// and spec clause, and an input that triggers it (a corpus program, a golden test input or
// link pair, or a file of docs/diagnostics/) with arbiter's real output. This test regenerates
// the page and compares, checks that every code has an example, and that the command-line
// codes written here are the ones cli/ and runtime/ define (tests/docs/guide_doc_test.py runs
// their examples); ARBITER_UPDATE_GOLDEN=1 rewrites the file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "arbiter/arbvp/check.h"
#include "arbiter/compiler/limits.h"
#include "arbiter/compiler/render.h"
#include "arbiter/glsl/check.h"
#include "arbiter/glsl/link.h"

namespace arbiter::arbvp {
namespace {

namespace fs = std::filesystem;

std::string ReadAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The limit profile a `--limits NAME` argument names: a built-in profile, or a JSON file
// relative to `dir`; nullopt when it names neither.
std::optional<compiler::LimitProfile> Profile(const std::string& name, const fs::path& dir) {
  if (const compiler::LimitProfile* builtin = compiler::BuiltinProfile(name)) return *builtin;
  std::string error;
  return compiler::LoadLimitProfile((dir / name).string(), &error);
}

// Runs the right checker on one file (by its extension) into `sink`, honouring the
// `ARGS: --limits NAME|FILE.json` / `--stage arbvp|arbfp` comment of golden inputs.
void CheckFile(const compiler::SourceFile& source, compiler::DiagnosticSink* sink) {
  if (std::optional<glsl::Stage> stage = glsl::StageFromPath(source.path())) {
    // A GLSL input's `ARGS: --link` judges it as a program, as `arbiter check --link`.
    glsl::CheckOptions glsl_options;
    size_t args = source.text().find("ARGS:");
    glsl_options.link =
        args != std::string::npos &&
        source.text().substr(args, source.text().find('\n', args) - args).find("--link") !=
            std::string::npos;
    glsl::CheckShader(*stage, {&source}, glsl_options, sink);
    return;
  }
  CheckOptions options;
  std::optional<compiler::LimitProfile> profile;
  const std::string& text = source.text();
  size_t args = text.find("ARGS:");
  if (args != std::string::npos) {
    std::string line = text.substr(args, text.find_first_of("\r\n", args) - args);
    size_t limits = line.find("--limits ");
    if (limits != std::string::npos) {
      std::string name = line.substr(limits + 9);
      name = name.substr(0, name.find(' '));
      profile = Profile(name, (fs::path(ARBITER_SOURCE_DIR) / source.path()).parent_path());
      EXPECT_TRUE(profile.has_value()) << source.path() << ": bad --limits " << name;
      options.profile = profile ? &*profile : nullptr;
    }
    if (line.find("--stage arbvp") != std::string::npos)
      options.expected_kind = ProgramKind::Vertex;
    if (line.find("--stage arbfp") != std::string::npos)
      options.expected_kind = ProgramKind::Fragment;
  }
  CheckProgram(source, options, sink);
}

// Where example inputs come from, in this order: the ARB corpus, the GLSL corpus, the golden
// CLI inputs, and docs/diagnostics/ for the codes none of those triggers.
constexpr const char* kExampleDirs[] = {"corpus/arb", "corpus/glsl", "tests/golden/check",
                                        "tests/golden/link", "docs/diagnostics"};

// Example program files (ARB and GLSL, each checked alone), repository-relative.
std::vector<std::string> ExampleFiles() {
  std::vector<std::string> names;
  for (const char* dir : kExampleDirs) {
    fs::path root = fs::path(ARBITER_SOURCE_DIR) / dir;
    if (!fs::exists(root)) continue;
    std::vector<std::string> found;
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
      std::string ext = entry.path().extension().string();
      if (entry.is_regular_file() &&
          (ext == ".vp" || ext == ".fp" || ext == ".vert" || ext == ".frag")) {
        found.push_back(fs::relative(entry.path(), ARBITER_SOURCE_DIR).generic_string());
      }
    }
    std::sort(found.begin(), found.end());
    names.insert(names.end(), found.begin(), found.end());
  }
  return names;
}

// One `arbiter link` example: a `*.args` file of tests/golden/link or docs/diagnostics that
// holds `link [--limits NAME] [--vert FILE...] [--frag FILE...] [FILE...]` and nothing else.
struct LinkExample {
  std::vector<std::string> vertex;    // repository-relative paths
  std::vector<std::string> fragment;  // repository-relative paths
  std::string limits;                 // "" or the --limits argument
  std::string command;                // `arbiter link ...` with repository-relative paths
};

std::optional<LinkExample> ParseLinkArgs(const fs::path& args_file) {
  std::istringstream in(ReadAll(args_file));
  std::vector<std::string> words;
  for (std::string word; in >> word;) words.push_back(word);
  if (words.empty() || words[0] != "link") return std::nullopt;
  std::string dir = fs::relative(args_file.parent_path(), ARBITER_SOURCE_DIR).generic_string();
  LinkExample example;
  example.command = "arbiter link";
  std::vector<std::string>* list = nullptr;  // after --vert or --frag
  for (size_t i = 1; i < words.size(); ++i) {
    const std::string& word = words[i];
    if (word == "--limits" && i + 1 < words.size()) {
      example.limits = words[++i];
      if (!Profile(example.limits, args_file.parent_path())) return std::nullopt;
      example.command += " --limits " + example.limits;
      continue;
    }
    if (word == "--vert" || word == "--frag") {
      list = word == "--vert" ? &example.vertex : &example.fragment;
      example.command += " " + word;
      continue;
    }
    if (word[0] == '-') return std::nullopt;  // other options: not a plain text example
    std::string path = dir + "/" + word;
    example.command += " " + path;
    if (list != nullptr) {
      list->push_back(path);
    } else if (std::optional<glsl::Stage> stage = glsl::StageFromPath(word)) {
      (*stage == glsl::Stage::Vertex ? example.vertex : example.fragment).push_back(path);
    } else {
      return std::nullopt;
    }
  }
  if (example.vertex.empty() || example.fragment.empty()) return std::nullopt;
  return example;
}

std::vector<LinkExample> LinkExamples() {
  std::vector<LinkExample> examples;
  for (const char* dir : kExampleDirs) {
    fs::path root = fs::path(ARBITER_SOURCE_DIR) / dir;
    if (!fs::exists(root)) continue;
    std::vector<fs::path> found;
    for (const auto& entry : fs::directory_iterator(root)) {
      if (entry.is_regular_file() && entry.path().extension() == ".args") {
        found.push_back(entry.path());
      }
    }
    std::sort(found.begin(), found.end());
    for (const fs::path& path : found) {
      if (std::optional<LinkExample> example = ParseLinkArgs(path)) examples.push_back(*example);
    }
  }
  return examples;
}

// The diagnostics of checking (or linking) an example, with the sources they point into.
struct Checked {
  std::vector<std::unique_ptr<compiler::SourceFile>> sources;
  std::vector<compiler::Diagnostic> diagnostics;
  size_t bytes = 0;  // the size of the inputs
};

Checked CheckExample(const std::string& name) {
  Checked checked;
  std::string text = ReadAll(fs::path(ARBITER_SOURCE_DIR) / name);
  checked.bytes = text.size();
  checked.sources.push_back(std::make_unique<compiler::SourceFile>(name, text));
  compiler::DiagnosticSink sink(0);
  CheckFile(*checked.sources.back(), &sink);
  checked.diagnostics = sink.diagnostics();
  return checked;
}

Checked LinkExampleChecked(const LinkExample& example) {
  Checked checked;
  auto load = [&](const std::vector<std::string>& paths) {
    std::vector<const compiler::SourceFile*> list;
    for (const std::string& path : paths) {
      std::string text = ReadAll(fs::path(ARBITER_SOURCE_DIR) / path);
      checked.bytes += text.size();
      checked.sources.push_back(std::make_unique<compiler::SourceFile>(path, text));
      list.push_back(checked.sources.back().get());
    }
    return list;
  };
  std::vector<const compiler::SourceFile*> vertex = load(example.vertex);
  std::vector<const compiler::SourceFile*> fragment = load(example.fragment);
  std::optional<compiler::LimitProfile> profile;
  glsl::LinkOptions options;
  if (!example.limits.empty()) {
    fs::path dir = (fs::path(ARBITER_SOURCE_DIR) / example.vertex.front()).parent_path();
    profile = Profile(example.limits, dir);
    options.profile = profile ? &*profile : nullptr;
  }
  compiler::DiagnosticSink sink(0);
  glsl::LinkProgram(vertex, fragment, options, &sink);
  checked.diagnostics = sink.diagnostics();
  return checked;
}

constexpr size_t kMaxExampleBytes = 1500;  // keep the page readable
constexpr std::string_view kDeliberateDir = "docs/diagnostics/";

// Corpus and golden inputs past kMaxExampleBytes are not used as examples; the files of
// docs/diagnostics/ are (a code may need a large input), shown with long lines clipped.
bool UsableExample(const std::string& name, size_t bytes) {
  return bytes <= kMaxExampleBytes || name.rfind(kDeliberateDir, 0) == 0;
}

// The text of an example as the page shows it: lines past 100 characters clipped.
std::string Shown(const std::string& text) {
  if (text.size() <= kMaxExampleBytes) return text;
  std::string out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.size() > 100) {
      line = line.substr(0, 60) + " ... (" + std::to_string(line.size()) + " characters)";
    }
    out += line + "\n";
  }
  return out;
}

// The first example whose checking reports each code: a file name, or an index into
// LinkExamples() for link examples.
struct ExampleRef {
  std::string file;
  int link = -1;
};

std::map<std::string, ExampleRef> Examples(const std::vector<LinkExample>& links) {
  std::map<std::string, ExampleRef> examples;
  for (const std::string& name : ExampleFiles()) {
    Checked checked = CheckExample(name);
    if (!UsableExample(name, checked.bytes)) continue;
    for (const compiler::Diagnostic& d : checked.diagnostics) {
      examples.emplace(std::string(d.info->code), ExampleRef{name, -1});
    }
  }
  for (size_t i = 0; i < links.size(); ++i) {
    Checked checked = LinkExampleChecked(links[i]);
    if (!UsableExample(links[i].vertex.front(), checked.bytes)) continue;
    for (const compiler::Diagnostic& d : checked.diagnostics) {
      examples.emplace(std::string(d.info->code), ExampleRef{"", static_cast<int>(i)});
    }
  }
  return examples;
}

// Codes of the table that no input is known to trigger, and why; each is a failure of a
// component, reported so that it is never silent. A code listed here that an example does
// trigger fails the test (the entry is stale).
const std::map<std::string, std::string>& NoExample() {
  static const std::map<std::string, std::string> codes = {
      {"arb-limit-portability",
       "No longer reported: without `--limits` arbiter enforces Mesa's limits and says nothing "
       "about the specification's minimums, which no GPU that ran ARB programs had; "
       "`--limits spec-min` reports a resource past the minimum as the error of its limit "
       "(`arb-limit-instructions`, `arb-binding-index-range`, ...). The code stays reserved."},
      {"glsl-link-limit-portability",
       "No longer reported: without `--limits` arbiter enforces Mesa's limits and says nothing "
       "about the GL 2.0 minimums; `--limits spec-min` reports a program past them as the "
       "error of its limit (`glsl-link-limit-uniforms`, ...). The code stays reserved."},
      {"glsl-internal-error",
       "It reports a failure of glslang itself (for instance a program it accepted "
       "stage by stage that it then cannot reflect); no known input triggers it."},
      {"glsl-link-error",
       "It reports a glslang link message that no other `glsl-link-*` code classifies, so "
       "that no program glslang refuses passes; arbiter's own link rules run first and "
       "report every known case with a precise code, and no known GLSL 1.10 input reaches "
       "it."},
  };
  return codes;
}

// The codes of the command line (cli/), which no library table holds: their entries are
// written here, with examples that tests/docs/guide_doc_test.py runs in docs/diagnostics/.
struct CommandLineCode {
  const char* code;
  const char* entry;
};

constexpr CommandLineCode kCommandLineCodes[] = {
    {"io-read",
     "**error**: an input could not be read (missing file, permission, a directory without\n"
     "programs). Exit code 3.\n\n"
     "Example, in `docs/diagnostics/`:\n\n"
     "```sh\n$ arbiter check missing.vp\n```\n\n"
     "```text\n"
     "missing.vp: error: cannot read 'missing.vp': no such file or directory [io-read]\n"
     "[exit 3]\n```\n\n"},
    {"driver-check-differs",
     "**note**: with `--driver-check`, Mesa's verdict on a GLSL shader differs from arbiter's;\n"
     "the note gives both verdicts and Mesa's first error line. It never changes the exit\n"
     "code. Where Mesa departs from GLSL 1.10 is listed in `docs/glsl-disagreements.md`.\n\n"
     "Example, in `docs/diagnostics/` (GLSL 1.10 does not reserve `dmat2`; Mesa does):\n\n"
     "```sh\n$ arbiter check --driver-check dmat2.vert\n```\n\n"
     "```text\n"
     "dmat2.vert:7:1: note: Mesa (softpipe) rejects this shader, arbiter accepts it; Mesa "
     "says: 0:7(7): error: illegal use of reserved word `dmat2' [driver-check-differs]\n"
     "float dmat2 = 1.0;\n"
     "^\n```\n\n"},
    {"glsl-stage-unknown",
     "**error**: a `.glsl` file whose name does not say its stage (`NAME.vert.glsl`,\n"
     "`NAME.frag.glsl`, `.vert`, `.vs`, `.vsh`, `.frag`, `.fs`, `.fsh`) and no `--stage`.\n\n"
     "Example, in `docs/diagnostics/`:\n\n"
     "```sh\n$ arbiter check shader.glsl\n```\n\n"
     "```text\n"
     "shader.glsl: error: cannot tell the stage of 'shader.glsl': name it NAME.vert.glsl or "
     "NAME.frag.glsl (or .vert, .frag, .vsh, .fsh), or give --stage vert|frag "
     "[glsl-stage-unknown]\n"
     "[exit 1]\n```\n\n"},
    {"runtime-gl-error",
     "**error**: a GL call failed while Mesa checked a shader for `--driver-check`, so Mesa's\n"
     "verdict is unknown. Exit code 3. It reports a failure of the driver, not of the shader;\n"
     "no known input triggers it.\n\n"},
};

std::vector<const compiler::DiagnosticInfo*> TableInfos() {
  std::vector<const compiler::DiagnosticInfo*> infos = AllDiagnostics();
  const auto& glsl_infos = glsl::AllDiagnostics();
  infos.insert(infos.end(), glsl_infos.begin(), glsl_infos.end());
  return infos;
}

// A fenced block of `text`, which may lack its final new-line.
// Grammar symbols such as <instruction> would be read as HTML tags by a Markdown renderer.
std::string EscapeMarkdown(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (c == '<' || c == '>') out += '\\';
    out += c;
  }
  return out;
}

std::string Block(const std::string& text) {
  std::string out = "```\n" + text;
  if (!text.empty() && text.back() != '\n') out += "\n";
  return out + "```\n\n";
}

std::string Generate() {
  std::vector<LinkExample> links = LinkExamples();
  std::map<std::string, ExampleRef> examples = Examples(links);
  std::string out =
      "# arbiter diagnostics\n\n"
      "Every diagnostic arbiter reports, generated from the tables in\n"
      "`arbvp/src/diagnostics.def` (ARB programs) and `glsl/src/diagnostics.def` (GLSL),\n"
      "and the command line's own codes, by `tests/docs/diagnostics_doc_test.cpp` (run it with\n"
      "`ARBITER_UPDATE_GOLDEN=1` to regenerate). Codes are stable: a code never changes\n"
      "meaning. Each entry shows an input that triggers it, from `corpus/`, `tests/golden/` or\n"
      "`docs/diagnostics/`, and arbiter's output for it: `arbiter check FILE` run from the\n"
      "repository's root (with the options of the file's `ARGS:` comment), or the `arbiter\n"
      "link` command shown. The test fails when a code has no example, unless the entry says\n"
      "why none can exist.\n\n"
      "Severities: an *error* rejects the program (exit code 1); a *warning* does not, unless\n"
      "`-Werror` is given. Limit checks (`arb-limit-*`, `arb-binding-index-range`,\n"
      "`glsl-link-limit-*`) depend on the profile: without `--limits`, exceeding what Mesa\n"
      "supports is an error and exceeding only the spec minimum is not reported; with\n"
      "`--limits PROFILE` (`spec-min`, `mesa`, a GPU such as `r300` or `i915`, or a JSON file),\n"
      "exceeding the profile is an error.\n\n";
  for (const CommandLineCode& code : kCommandLineCodes) {
    out += "## " + std::string(code.code) + "\n\n" + code.entry;
  }
  for (const compiler::DiagnosticInfo* info : TableInfos()) {
    const std::string code(info->code);
    out += "## " + code + "\n\n";
    out += "**" + std::string(compiler::SeverityName(info->severity)) +
           "**: " + EscapeMarkdown(info->summary) + ".";
    if (!info->spec_ref.empty()) out += " Spec: " + EscapeMarkdown(info->spec_ref) + ".";
    out += "\n\n";
    auto it = examples.find(code);
    if (it == examples.end()) {
      auto none = NoExample().find(code);
      out += none != NoExample().end() ? none->second + "\n\n"
                                       : std::string("No example input triggers it yet.\n\n");
      continue;
    }
    const ExampleRef& ref = it->second;
    Checked checked;
    if (ref.link < 0) {
      checked = CheckExample(ref.file);
      out += "Example, `" + ref.file + "`:\n\n" + Block(Shown(checked.sources.front()->text()));
    } else {
      checked = LinkExampleChecked(links[static_cast<size_t>(ref.link)]);
      out += "Example, `" + links[static_cast<size_t>(ref.link)].command + "`:\n\n";
      for (const auto& source : checked.sources) {
        out += "`" + source->path() + "`:\n\n" + Block(Shown(source->text()));
      }
    }
    compiler::FileReport report;
    for (const compiler::Diagnostic& d : checked.diagnostics) {
      if (d.info->code == info->code) {
        report.path = d.file != nullptr ? d.file->path() : checked.sources.front()->path();
        report.diagnostics.push_back(d);
        break;
      }
    }
    out += Block(compiler::RenderText(report, compiler::TextOptions{}));
  }
  return out;
}

TEST(DiagnosticsDoc, MatchesTheTable) {
  fs::path doc = fs::path(ARBITER_SOURCE_DIR) / "docs" / "diagnostics.md";
  std::string expected = Generate();
  if (std::getenv("ARBITER_UPDATE_GOLDEN")) {
    std::ofstream(doc, std::ios::binary) << expected;
  }
  EXPECT_EQ(ReadAll(doc), expected)
      << "docs/diagnostics.md is out of date: rerun with ARBITER_UPDATE_GOLDEN=1";
}

TEST(DiagnosticsDoc, EveryCodeIsUniqueAndKebabCase) {
  std::set<std::string_view> seen;
  for (const CommandLineCode& code : kCommandLineCodes) seen.insert(code.code);
  for (const compiler::DiagnosticInfo* info : TableInfos()) {
    EXPECT_TRUE(seen.insert(info->code).second) << info->code;
    EXPECT_TRUE(info->code.substr(0, 4) == "arb-" || info->code.substr(0, 5) == "glsl-")
        << info->code;
    for (char c : info->code)
      EXPECT_TRUE(std::islower(c) || std::isdigit(c) || c == '-') << info->code;
    EXPECT_FALSE(info->summary.empty());
    EXPECT_NE(info->summary.back(), '.') << info->code << ": summaries end without a period";
  }
}

// Each code of the tables is triggered by an example (checking the example reports it, which is
// how Examples() finds it), or is listed in NoExample() with the reason; not both.
TEST(DiagnosticsDoc, EveryCodeHasAnExample) {
  std::map<std::string, ExampleRef> examples = Examples(LinkExamples());
  std::set<std::string> codes;
  for (const compiler::DiagnosticInfo* info : TableInfos()) {
    const std::string code(info->code);
    codes.insert(code);
    const bool listed = NoExample().count(code) > 0;
    if (listed) {
      EXPECT_EQ(examples.count(code), 0u)
          << code << " has an example now: remove it from NoExample()";
    } else {
      EXPECT_EQ(examples.count(code), 1u)
          << code << ": no input of " << kExampleDirs[0]
          << ", ... or docs/diagnostics/ triggers it; add one (docs/diagnostics/ takes files "
             "and link .args files)";
    }
  }
  for (const auto& [code, reason] : NoExample()) EXPECT_EQ(codes.count(code), 1u) << code;
}

// The command line defines its own DiagnosticInfo values (cli/, runtime/): every one has its
// entry in kCommandLineCodes and no entry is stale. An entry with an example shows the code.
TEST(DiagnosticsDoc, CommandLineCodesAreDocumented) {
  static const std::regex kDefinition(R"re(DiagnosticInfo\s+\w+\s*\{\s*"([a-z0-9-]+)")re");
  std::set<std::string> defined;
  for (const char* dir : {"cli", "runtime"}) {
    for (const auto& entry : fs::recursive_directory_iterator(fs::path(ARBITER_SOURCE_DIR) / dir)) {
      std::string ext = entry.path().extension().string();
      if (!entry.is_regular_file() || (ext != ".cpp" && ext != ".h")) continue;
      std::string text = ReadAll(entry.path());
      for (std::sregex_iterator it(text.begin(), text.end(), kDefinition), end; it != end; ++it) {
        defined.insert((*it)[1].str());
      }
    }
  }
  std::set<std::string> documented;
  for (const CommandLineCode& code : kCommandLineCodes) {
    documented.insert(code.code);
    std::string entry(code.entry);
    if (entry.find("```sh") != std::string::npos) {
      EXPECT_NE(entry.find("[" + std::string(code.code) + "]"), std::string::npos) << code.code;
    }
  }
  EXPECT_EQ(defined, documented);
}

}  // namespace
}  // namespace arbiter::arbvp
