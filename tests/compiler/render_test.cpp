// Tests of the text, JSON and SARIF renderers: exact cases and golden files.
//
// Golden files live in tests/compiler/golden/; ARBITER_UPDATE_GOLDEN=1 rewrites them from
// the current output (review the diff before committing).
#include "arbiter/compiler/render.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "arbiter/compiler/source.h"
#include "nlohmann/json.hpp"

namespace arbiter::compiler {
namespace {

using nlohmann::json;

constexpr DiagnosticInfo kUnknownBinding{"arb-binding-unknown", Severity::Error, "unknown binding",
                                         "ARBfp 3.11.2"};
constexpr DiagnosticInfo kRedeclared{"arb-decl-redeclared", Severity::Error,
                                     "a name is declared twice", "ARBfp 3.11.3.1"};
constexpr DiagnosticInfo kBadConstant{"arb-syntax-constant", Severity::Error, "malformed constant",
                                      ""};
constexpr DiagnosticInfo kUnused{"arb-unused-param", Severity::Warning, "a parameter is never read",
                                 ""};
constexpr DiagnosticInfo kNoNewline{"arb-syntax-no-final-newline", Severity::Warning,
                                    "the file does not end with a newline", ""};
constexpr DiagnosticInfo kStats{"arb-info-stats", Severity::Note, "resource usage", ""};
constexpr DiagnosticInfo kIoRead{"io-read", Severity::Error, "an input cannot be read", ""};

// The range of the `nth` occurrence of `needle` in `text`.
Range Find(std::string_view text, std::string_view needle, int nth = 0) {
  size_t pos = text.find(needle);
  for (int i = 0; i < nth && pos != std::string_view::npos; ++i) {
    pos = text.find(needle, pos + 1);
  }
  EXPECT_NE(pos, std::string_view::npos) << "'" << needle << "' not in the text";
  return Range{static_cast<uint32_t>(pos), static_cast<uint32_t>(pos + needle.size())};
}

Diagnostic MakeDiag(const DiagnosticInfo& info, const SourceFile* file, Range range,
                    std::string message) {
  Diagnostic diag;
  diag.info = &info;
  diag.severity = info.severity;
  diag.file = file;
  diag.range = range;
  diag.message = std::move(message);
  return diag;
}

// ---------------------------------------------------------------------------------------
// Exact cases of the text format.

std::string RenderOne(const SourceFile& file, Range range, const TextOptions& options = {}) {
  FileReport report;
  report.path = file.path();
  report.diagnostics.push_back(MakeDiag(kBadConstant, &file, range, "bad"));
  return RenderText(report, options);
}

TEST(RenderTextTest, CaretAndTildesUnderTheRange) {
  const SourceFile file("a.fp", "MOV r0, 1.0e;\n");
  EXPECT_EQ(RenderOne(file, Find(file.text(), "1.0e")),
            "a.fp:1:9: error: bad [arb-syntax-constant]\n"
            "MOV r0, 1.0e;\n"
            "        ^~~~\n");
}

TEST(RenderTextTest, ZeroLengthRangeIsOneCaret) {
  const SourceFile file("a.fp", "MOV r0, r1\n");
  EXPECT_EQ(RenderOne(file, {4, 4}),
            "a.fp:1:5: error: bad [arb-syntax-constant]\n"
            "MOV r0, r1\n"
            "    ^\n");
}

TEST(RenderTextTest, EndOfFileWithoutNewline) {
  const SourceFile file("a.fp", "!!ARBfp1.0\nMOV r0, r1");
  EXPECT_EQ(RenderOne(file, {21, 21}),
            "a.fp:2:11: error: bad [arb-syntax-constant]\n"
            "MOV r0, r1\n"
            "          ^\n");
}

TEST(RenderTextTest, EndOfFileAfterNewlineIsAfterTheLastLine) {
  const SourceFile file("a.fp", "!!ARBfp1.0\nMOV r0, r1\n");
  EXPECT_EQ(RenderOne(file, {22, 22}),
            "a.fp:2:11: error: bad [arb-syntax-constant]\n"
            "MOV r0, r1\n"
            "          ^\n");
}

TEST(RenderTextTest, RangeOverSeveralLinesStopsAtTheEndOfTheFirst) {
  const SourceFile file("a.fp", "MOV r0,\n  r1;\n");
  EXPECT_EQ(RenderOne(file, {4, 12}),
            "a.fp:1:5: error: bad [arb-syntax-constant]\n"
            "MOV r0,\n"
            "    ^~~\n");
}

TEST(RenderTextTest, TabsExpandToEightColumns) {
  const SourceFile file("a.fp", "\tMOV r0,\tr1;\n");
  EXPECT_EQ(RenderOne(file, Find(file.text(), "r1")),
            "a.fp:1:10: error: bad [arb-syntax-constant]\n"
            "        MOV r0, r1;\n"
            "                ^~\n");
  // A range over a tab covers its columns.
  EXPECT_EQ(RenderOne(file, {7, 10}),
            "a.fp:1:8: error: bad [arb-syntax-constant]\n"
            "        MOV r0, r1;\n"
            "              ^~~\n");
}

TEST(RenderTextTest, TrailingBlanksAreTrimmed) {
  const SourceFile file("a.fp", "END  \t \n");
  EXPECT_EQ(RenderOne(file, {0, 3}),
            "a.fp:1:1: error: bad [arb-syntax-constant]\n"
            "END\n"
            "^~~\n");
}

TEST(RenderTextTest, Utf8CharactersTakeOneColumn) {
  const SourceFile file("a.fp", "# caf\xC3\xA9 \xE2\x82\xAC x\n");
  EXPECT_EQ(RenderOne(file, Find(file.text(), "x")),
            "a.fp:1:10: error: bad [arb-syntax-constant]\n"
            "# caf\xC3\xA9 \xE2\x82\xAC x\n"
            "         ^\n");
}

TEST(RenderTextTest, InvalidBytesAndControlCharactersStayPrintable) {
  const SourceFile file("a.fp", std::string("#\xFF\x1b[31m\0x\n", 10));
  EXPECT_EQ(RenderOne(file, Find(file.text(), "x")),
            "a.fp:1:9: error: bad [arb-syntax-constant]\n"
            "#? [31m x\n"
            "        ^\n");
}

TEST(RenderTextTest, C1ControlCharactersAreNotPrinted) {
  // U+009B is CSI, an escape introducer for some terminals.
  const SourceFile file("a.fp",
                        "#\xC2\x9B"
                        "31m x\n");
  EXPECT_EQ(RenderOne(file, Find(file.text(), "x")),
            "a.fp:1:7: error: bad [arb-syntax-constant]\n"
            "# 31m x\n"
            "      ^\n");
}

TEST(RenderTextTest, CrLfAndLfRenderAlike) {
  const SourceFile lf("a.fp", "!!ARBfp1.0\nMOV r0, 1.0e;\nEND\n");
  const SourceFile crlf("a.fp", "!!ARBfp1.0\r\nMOV r0, 1.0e;\r\nEND\r\n");
  EXPECT_EQ(RenderOne(lf, Find(lf.text(), "1.0e")), RenderOne(crlf, Find(crlf.text(), "1.0e")));
  const SourceFile cr("a.fp", "!!ARBfp1.0\rMOV r0, 1.0e;\rEND\r");
  EXPECT_EQ(RenderOne(lf, Find(lf.text(), "1.0e")), RenderOne(cr, Find(cr.text(), "1.0e")));
}

TEST(RenderTextTest, LongLineClippedAroundTheCaret) {
  std::string text(150, 'a');
  text += "XYZ";
  text += std::string(150, 'b');
  const SourceFile file("a.fp", text);
  const std::string out = RenderOne(file, Find(text, "XYZ"));
  // Window of 160 columns from 80 before the caret, "..." on both sides.
  const std::string expected = "a.fp:1:151: error: bad [arb-syntax-constant]\n..." +
                               std::string(80, 'a') + "XYZ" + std::string(77, 'b') + "...\n" +
                               std::string(83, ' ') + "^~~\n";
  EXPECT_EQ(out, expected);
}

TEST(RenderTextTest, LineOfTwoHundredColumnsIsNotClipped) {
  const SourceFile file("a.fp", std::string(199, 'a') + "Z");
  EXPECT_EQ(RenderOne(file, {199, 200}), "a.fp:1:200: error: bad [arb-syntax-constant]\n" +
                                             std::string(199, 'a') + "Z\n" + std::string(199, ' ') +
                                             "^\n");
}

TEST(RenderTextTest, NoSourceLines) {
  const SourceFile file("a.fp", "MOV r0, 1.0e;\n");
  TextOptions options;
  options.show_source = false;
  EXPECT_EQ(RenderOne(file, Find(file.text(), "1.0e"), options),
            "a.fp:1:9: error: bad [arb-syntax-constant]\n");
}

TEST(RenderTextTest, FileLessDiagnosticAndNoteWithoutLocation) {
  FileReport report;
  report.path = "missing.vp";
  Diagnostic diag = MakeDiag(kIoRead, nullptr, {}, "cannot read file: no such file or directory");
  diag.notes.push_back(Note{nullptr, {}, "arguments are paths relative to the working folder"});
  report.diagnostics.push_back(diag);
  EXPECT_EQ(RenderText(report, {}),
            "missing.vp: error: cannot read file: no such file or directory [io-read]\n"
            "note: arguments are paths relative to the working folder\n");
  // Its own path wins over the report's.
  report.diagnostics[0].path = "other.vp";
  EXPECT_EQ(RenderText(report, {}).substr(0, 10), "other.vp: ");
}

TEST(RenderTextTest, DroppedErrorsLine) {
  FileReport report;
  report.path = "a.fp";
  report.dropped_errors = 1;
  EXPECT_EQ(RenderText(report, {}), "a.fp: note: 1 more error not shown (--error-limit)\n");
  report.dropped_errors = 7;
  EXPECT_EQ(RenderText(report, {}), "a.fp: note: 7 more errors not shown (--error-limit)\n");
}

TEST(RenderTextTest, EmptyReportRendersNothing) {
  FileReport report;
  report.path = "a.fp";
  EXPECT_EQ(RenderText(report, {}), "");
  EXPECT_EQ(RenderText(report, {true, true}), "");
}

// ---------------------------------------------------------------------------------------
// Golden files.

// Control characters made visible for failure messages.
std::string Visible(std::string_view line) {
  std::string out;
  for (const char c : line) {
    if (c == '\x1b') {
      out += "\\e";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c == '\r') {
      out += "\\r";
    } else {
      out += c;
    }
  }
  return out;
}

std::vector<std::string> SplitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream stream(text);
  for (std::string line; std::getline(stream, line);) {
    lines.push_back(line);
  }
  if (!text.empty() && text.back() != '\n') {
    lines.back() += "<no newline at end>";
  }
  return lines;
}

// A line-by-line comparison: the first differences with their line numbers.
std::string DiffMessage(const std::string& path, const std::string& expected,
                        const std::string& actual) {
  const std::vector<std::string> want = SplitLines(expected);
  const std::vector<std::string> got = SplitLines(actual);
  std::ostringstream message;
  message << "output differs from golden file " << path << "\n"
          << "(rerun with ARBITER_UPDATE_GOLDEN=1 to accept the new output)\n"
          << "--- expected\n+++ actual\n";
  int shown = 0;
  for (size_t i = 0; i < std::max(want.size(), got.size()) && shown < 20; ++i) {
    const bool has_want = i < want.size();
    const bool has_got = i < got.size();
    if (has_want && has_got && want[i] == got[i]) {
      continue;
    }
    message << "@@ line " << i + 1 << "\n";
    if (has_want) {
      message << "-" << Visible(want[i]) << "\n";
    }
    if (has_got) {
      message << "+" << Visible(got[i]) << "\n";
    }
    ++shown;
  }
  return message.str();
}

// Compares `actual` with golden file `name` byte for byte (or rewrites it on request).
void ExpectGolden(const std::string& name, const std::string& actual) {
  const std::string path = std::string(ARBITER_TEST_DIR) + "/golden/" + name;
  const char* update = std::getenv("ARBITER_UPDATE_GOLDEN");
  std::string error;
  if (update != nullptr && std::string_view(update) == "1") {
    ASSERT_TRUE(WriteFileAtomically(path, actual, &error)) << path << ": " << error;
    std::cout << "updated " << path << "\n";
    return;
  }
  std::string expected;
  ASSERT_TRUE(ReadFileBytes(path, &expected, &error))
      << "cannot read golden file " << path << ": " << error
      << " (run with ARBITER_UPDATE_GOLDEN=1 to create it)";
  if (expected != actual) {
    ADD_FAILURE() << DiffMessage(path, expected, actual);
  }
}

// A fragment program with one diagnostic of every shape: a tab, UTF-8, a redeclaration
// with a note, a long line, a range over two lines, the end of the file, a note into
// another file, a file-less note, a standalone note; three errors past the limit.
class GoldenTest : public ::testing::Test {
 protected:
  GoldenTest()
      : main_("shaders/bad.fp", MainText()),
        vertex_("shaders/pair.vp", "!!ARBvp1.0\nOUTPUT oTex = result.texcoord[1];\nEND\n") {
    const std::string& text = main_.text();
    FileReport report;
    report.path = "shaders/bad.fp";
    Diagnostic* diag = nullptr;

    diag = &report.diagnostics.emplace_back(MakeDiag(kRedeclared, &main_, Find(text, "r0", 1),
                                                     "'r0' is already declared in this program"));
    diag->notes.push_back(Note{&main_, Find(text, "r0", 0), "'r0' first declared here"});

    diag = &report.diagnostics.emplace_back(MakeDiag(kUnknownBinding, &main_,
                                                     Find(text, "fragment.colr"),
                                                     "unknown fragment attribute 'fragment.colr'"));
    diag->notes.push_back(Note{nullptr, {}, "did you mean 'fragment.color'?"});

    report.diagnostics.push_back(
        MakeDiag(kUnused, &main_, Find(text, "lait"), "comment mentions 'lait' (a UTF-8 line)"));

    report.diagnostics.push_back(
        MakeDiag(kUnused, &main_, Find(text, "big"), "parameter 'big' is never read"));
    report.diagnostics.push_back(
        MakeDiag(kBadConstant, &main_, Find(text, "9.9.9"), "malformed constant '9.9.9'"));
    report.diagnostics.push_back(
        MakeDiag(kBadConstant, &main_, Find(text, "7e"), "malformed constant '7e'"));

    diag = &report.diagnostics.emplace_back(
        MakeDiag(kUnknownBinding, &main_, Find(text, "fragment.texcoord[1]"),
                 "'fragment.texcoord[1]' is not written by the vertex program"));
    diag->notes.push_back(Note{&vertex_, Find(vertex_.text(), "result.texcoord[1]"),
                               "the vertex program writes 'result.texcoord[1]' here"});
    diag->range.end = Find(text, "r1;").end;  // over two lines

    report.diagnostics.push_back(
        MakeDiag(kStats, &main_, Find(text, "!!ARBfp1.0"), "3 ALU and 1 TEX instructions"));

    const auto size = static_cast<uint32_t>(text.size());
    report.diagnostics.push_back(
        MakeDiag(kNoNewline, &main_, {size, size}, "missing newline at the end of the file"));
    report.dropped_errors = 3;
    reports_.push_back(std::move(report));

    FileReport missing;
    missing.path = "shaders/missing file.vp";
    missing.diagnostics.push_back(
        MakeDiag(kIoRead, nullptr, {}, "cannot read input: no such file or directory"));
    reports_.push_back(std::move(missing));

    FileReport clean;
    clean.path = "shaders\\clean.vp";
    reports_.push_back(std::move(clean));
  }

  static std::string MainText() {
    std::string long_line = "PARAM big[] = { ";
    for (int i = 0; i < 20; ++i) {
      long_line += "{1,2,3,4}, ";
    }
    long_line += "{1,2,9.9.9,4}, ";
    for (int i = 0; i < 20; ++i) {
      long_line += "{1,2,3,4}, ";
    }
    long_line += "{7e} };";
    return "!!ARBfp1.0\n"
           "# caf\xC3\xA9 au lait \xE2\x82\xAC\n"
           "TEMP r0, r0;\n"
           "\tMOV r0, fragment.colr;\t \n" +
           long_line +
           "\n"
           "ADD r0, fragment.texcoord[1],\n"
           "        r1;\n"
           "END";
  }

  SourceFile main_;
  SourceFile vertex_;
  std::vector<FileReport> reports_;
};

TEST_F(GoldenTest, Text) { ExpectGolden("render_text.txt", RenderText(reports_[0], {})); }

TEST_F(GoldenTest, TextColor) {
  TextOptions options;
  options.color = true;
  ExpectGolden("render_text_color.txt", RenderText(reports_[0], options));
}

TEST_F(GoldenTest, TextOfAFileLessDiagnostic) {
  ExpectGolden("render_text_io.txt", RenderText(reports_[1], {}));
}

TEST_F(GoldenTest, Json) { ExpectGolden("render.json", RenderJson(reports_)); }

TEST_F(GoldenTest, Sarif) { ExpectGolden("render.sarif", RenderSarif(reports_, "0.1.0")); }

TEST_F(GoldenTest, RenderingIsDeterministic) {
  EXPECT_EQ(RenderJson(reports_), RenderJson(reports_));
  EXPECT_EQ(RenderSarif(reports_, "0.1.0"), RenderSarif(reports_, "0.1.0"));
}

TEST_F(GoldenTest, JsonStructure) {
  const json doc = json::parse(RenderJson(reports_));
  ASSERT_EQ(doc["files"].size(), 3u);
  const json& bad = doc["files"][0];
  EXPECT_EQ(bad["path"], "shaders/bad.fp");
  // Errors count the ones past the limit too.
  EXPECT_EQ(bad["errors"], 5 + 3);
  EXPECT_EQ(bad["warnings"], 3);
  EXPECT_EQ(bad["dropped_errors"], 3);
  // In line order (issue 22): the stats note of line 1 first.
  int previous_line = 0;
  for (const json& d : bad["diagnostics"]) {
    EXPECT_GE(d["line"].get<int>(), previous_line) << d["code"];
    previous_line = d["line"].get<int>();
  }
  EXPECT_EQ(bad["diagnostics"][0]["code"], "arb-info-stats");
  const json& first = bad["diagnostics"][2];
  EXPECT_EQ(first["code"], "arb-decl-redeclared");
  EXPECT_EQ(first["severity"], "error");
  EXPECT_EQ(first["line"], 3);
  EXPECT_EQ(first["column"], 10);
  EXPECT_EQ(first["end_line"], 3);
  EXPECT_EQ(first["end_column"], 12);
  EXPECT_EQ(first["offset"], main_.text().find("r0, r0") + 4);
  EXPECT_EQ(first["length"], 2);
  EXPECT_EQ(first["notes"][0]["column"], 6);
  EXPECT_FALSE(first.contains("path"));
  // A note into another file names it.
  bool other_file_note = false;
  for (const json& d : bad["diagnostics"]) {
    for (const json& n : d["notes"]) other_file_note |= n.value("path", "") == "shaders/pair.vp";
  }
  EXPECT_TRUE(other_file_note);
  // A file-less diagnostic has null positions.
  const json& io = doc["files"][1]["diagnostics"][0];
  EXPECT_TRUE(io["line"].is_null());
  EXPECT_TRUE(io["offset"].is_null());
  EXPECT_EQ(doc["summary"], json({{"files", 3}, {"errors", 9}, {"warnings", 3}}));
}

// Required properties of a SARIF 2.1.0 log (sarif-schema-2.1.0.json) and our own promises.
void ExpectValidLocation(const json& location) {
  ASSERT_TRUE(location.is_object());
  if (!location.contains("physicalLocation")) {
    EXPECT_TRUE(location["message"]["text"].is_string()) << location;
    return;
  }
  const json& physical = location["physicalLocation"];
  EXPECT_TRUE(physical["artifactLocation"]["uri"].is_string()) << location;
  const std::string uri = physical["artifactLocation"]["uri"];
  EXPECT_EQ(uri.find_first_of(" \\#?"), std::string::npos) << uri;
  if (physical.contains("region")) {
    const json& region = physical["region"];
    for (const char* key :
         {"startLine", "startColumn", "endLine", "endColumn", "byteOffset", "byteLength"}) {
      ASSERT_TRUE(region[key].is_number_integer()) << key << " in " << region;
    }
    EXPECT_GE(region["startLine"].get<int>(), 1);
    EXPECT_GE(region["startColumn"].get<int>(), 1);
    EXPECT_GE(region["endLine"].get<int>(), region["startLine"].get<int>());
    if (region["endLine"] == region["startLine"]) {
      EXPECT_GE(region["endColumn"].get<int>(), region["startColumn"].get<int>());
    }
    EXPECT_GE(region["byteOffset"].get<int>(), 0);
    EXPECT_GE(region["byteLength"].get<int>(), 0);
  }
}

void ExpectValidSarif(const json& log) {
  ASSERT_TRUE(log.is_object());
  EXPECT_EQ(log["$schema"], "https://json.schemastore.org/sarif-2.1.0.json");
  EXPECT_EQ(log["version"], "2.1.0");
  ASSERT_TRUE(log["runs"].is_array());
  ASSERT_EQ(log["runs"].size(), 1u);
  const json& run = log["runs"][0];
  const json& driver = run["tool"]["driver"];
  EXPECT_EQ(driver["name"], "arbiter");
  EXPECT_TRUE(driver["version"].is_string());
  EXPECT_TRUE(driver["informationUri"].is_string());
  ASSERT_TRUE(driver["rules"].is_array());
  std::set<std::string> ids;
  for (const json& rule : driver["rules"]) {
    ASSERT_TRUE(rule["id"].is_string());
    EXPECT_TRUE(ids.insert(rule["id"].get<std::string>()).second) << "duplicate rule " << rule;
    EXPECT_TRUE(rule["shortDescription"]["text"].is_string());
    EXPECT_TRUE(rule["fullDescription"]["text"].is_string());
    // Code-scanning services show `help` with each result (SARIF 2.1.0 3.49.13).
    EXPECT_TRUE(rule["help"]["text"].is_string()) << rule;
    EXPECT_TRUE(rule["help"]["markdown"].is_string()) << rule;
    EXPECT_EQ(rule["helpUri"],
              "https://github.com/arbiter-shaders/arbiter/blob/main/docs/diagnostics.md#" +
                  rule["id"].get<std::string>());
    const std::string level = rule["defaultConfiguration"]["level"];
    EXPECT_TRUE(level == "error" || level == "warning" || level == "note") << level;
  }
  ASSERT_TRUE(run["results"].is_array());
  for (const json& result : run["results"]) {
    EXPECT_TRUE(result["message"]["text"].is_string()) << result;
    const std::string level = result["level"];
    EXPECT_TRUE(level == "error" || level == "warning" || level == "note") << level;
    if (result.contains("ruleId")) {
      const size_t index = result["ruleIndex"];
      ASSERT_LT(index, driver["rules"].size());
      EXPECT_EQ(driver["rules"][index]["id"], result["ruleId"]);
    }
    ASSERT_TRUE(result["locations"].is_array());
    for (const json& location : result["locations"]) {
      ExpectValidLocation(location);
    }
    if (result.contains("relatedLocations")) {
      for (const json& location : result["relatedLocations"]) {
        ExpectValidLocation(location);
        EXPECT_TRUE(location["message"]["text"].is_string());
      }
    }
  }
  if (run.contains("invocations")) {
    for (const json& invocation : run["invocations"]) {
      EXPECT_TRUE(invocation["executionSuccessful"].is_boolean());
    }
  }
}

TEST_F(GoldenTest, SarifStructure) {
  std::string golden;
  std::string error;
  ASSERT_TRUE(
      ReadFileBytes(std::string(ARBITER_TEST_DIR) + "/golden/render.sarif", &golden, &error))
      << error;
  ExpectValidSarif(json::parse(golden));
  const json log = json::parse(RenderSarif(reports_, "0.1.0"));
  ExpectValidSarif(log);
  // Rules: one per code, in first-use order, the results being in line order (the stats
  // note is on line 1, the unused parameter on line 2).
  std::vector<std::string> ids;
  for (const json& rule : log["runs"][0]["tool"]["driver"]["rules"]) {
    ids.push_back(rule["id"]);
  }
  EXPECT_EQ(ids,
            (std::vector<std::string>{"arb-info-stats", "arb-unused-param", "arb-decl-redeclared",
                                      "arb-binding-unknown", "arb-syntax-constant",
                                      "arb-syntax-no-final-newline", "io-read"}));
  const json& rule = log["runs"][0]["tool"]["driver"]["rules"][2];
  EXPECT_EQ(rule["fullDescription"]["text"], "a name is declared twice (ARBfp 3.11.3.1)");
  const std::string doc =
      "https://github.com/arbiter-shaders/arbiter/blob/main/docs/diagnostics.md#";
  EXPECT_EQ(rule["help"]["text"],
            "error: a name is declared twice. Spec: ARBfp 3.11.3.1. Documentation: " + doc +
                "arb-decl-redeclared");
  EXPECT_EQ(rule["help"]["markdown"],
            "**error**: a name is declared twice. Spec: ARBfp 3.11.3.1.\n\n"
            "[`arb-decl-redeclared` in arbiter's diagnostics](" +
                doc + "arb-decl-redeclared)");
  // A code without a spec clause: no "Spec:" sentence.
  const json& io_rule = log["runs"][0]["tool"]["driver"]["rules"][6];
  EXPECT_EQ(io_rule["help"]["text"],
            "error: an input cannot be read. Documentation: " + doc + "io-read");
  EXPECT_EQ(log["runs"][0]["results"].size(), 10u);
  const json& result = log["runs"][0]["results"][9];
  EXPECT_EQ(result["locations"][0]["physicalLocation"]["artifactLocation"]["uri"],
            "shaders/missing%20file.vp");
}

TEST(RenderSarifTest, EmptyLogIsValid) {
  const json log = json::parse(RenderSarif({}, "0.1.0"));
  ExpectValidSarif(log);
  EXPECT_TRUE(log["runs"][0]["results"].empty());
  EXPECT_TRUE(log["runs"][0]["tool"]["driver"]["rules"].empty());
}

TEST(RenderSarifTest, HelpMarkdownEscapesGrammarSymbols) {
  constexpr DiagnosticInfo kSaturate{"arb-syntax-saturate-vp", Severity::Error,
                                     "_SAT is a fragment-program suffix",
                                     "ARBvp 2.14.2 <instruction>"};
  FileReport report;
  report.path = "a.vp";
  report.diagnostics.push_back(MakeDiag(kSaturate, nullptr, {}, "'MOV_SAT' in a vertex program"));
  const json log = json::parse(RenderSarif({report}, "0.1.0"));
  const json& help = log["runs"][0]["tool"]["driver"]["rules"][0]["help"];
  // Markdown would take '<instruction>' for an HTML tag and '_' for emphasis; text keeps them.
  const std::string markdown = help["markdown"];
  EXPECT_EQ(
      markdown.substr(0, markdown.find("\n\n")),
      "**error**: \\_SAT is a fragment-program suffix. Spec: ARBvp 2.14.2 \\<instruction\\>.");
  const std::string text = help["text"];
  EXPECT_EQ(text.substr(0, text.find(" Documentation: ")),
            "error: _SAT is a fragment-program suffix. Spec: ARBvp 2.14.2 <instruction>.");
}

TEST(RenderJsonTest, EmptyDocument) {
  EXPECT_EQ(RenderJson({}),
            "{\n"
            "  \"files\": [],\n"
            "  \"summary\": {\n"
            "    \"files\": 0,\n"
            "    \"errors\": 0,\n"
            "    \"warnings\": 0\n"
            "  }\n"
            "}\n");
}

TEST(RenderJsonTest, InvalidUtf8InAMessageIsReplaced) {
  FileReport report;
  report.path = "a.fp";
  report.diagnostics.push_back(MakeDiag(kBadConstant, nullptr, {}, "bad byte '\xFF'"));
  const json doc = json::parse(RenderJson({report}));
  EXPECT_EQ(doc["files"][0]["diagnostics"][0]["message"], "bad byte '\xEF\xBF\xBD'");
  const json log = json::parse(RenderSarif({report}, "0.1.0"));
  EXPECT_EQ(log["runs"][0]["results"][0]["message"]["text"], "bad byte '\xEF\xBF\xBD'");
}

}  // namespace
}  // namespace arbiter::compiler
