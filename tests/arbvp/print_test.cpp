// PrintProgram: every valid corpus program parses, prints, and parses again into the same
// variables and instructions.
#include "arbiter/arbvp/print.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "arbiter/arbvp/check.h"

namespace arbiter::arbvp {
namespace {

namespace fs = std::filesystem;

// Relative to corpus/arb: the valid programs and the valid NV option programs.
std::vector<std::string> ValidFiles() {
  std::vector<std::string> files;
  const fs::path corpus = fs::path(ARBITER_SOURCE_DIR) / "corpus" / "arb";
  for (const char* folder : {"valid", "valid-nv"}) {
    if (!fs::exists(corpus / folder)) continue;
    for (const auto& entry : fs::recursive_directory_iterator(corpus / folder)) {
      std::string ext = entry.path().extension().string();
      if (entry.is_regular_file() && (ext == ".vp" || ext == ".fp")) {
        files.push_back(fs::relative(entry.path(), corpus).generic_string());
      }
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string ReadAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

CheckResult Check(const std::string& name, const std::string& text, std::string* log) {
  compiler::SourceFile source(name, text);
  compiler::DiagnosticSink sink(0);
  CheckResult result = CheckProgram(source, CheckOptions{}, &sink);
  for (const compiler::Diagnostic& d : sink.diagnostics()) {
    compiler::LineCol lc = source.Locate(d.range.begin);
    *log += std::to_string(lc.line) + ":" + std::to_string(lc.column) + " " + d.message + "\n";
  }
  return result;
}

// Floats compared by bits, so that -0 and +0 differ and inf matches inf.
bool SameFloat(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// The binding's meaning (not its source ranges).
std::string Describe(const Binding& b) {
  std::string text =
      std::to_string(static_cast<int>(b.kind)) + " " + BindingName(b, ProgramKind::Vertex);
  return text;
}

void ExpectSameBinding(const Binding& a, const Binding& b) {
  EXPECT_EQ(a.kind, b.kind);
  EXPECT_EQ(Describe(a), Describe(b));
  EXPECT_EQ(a.vertex_attrib, b.vertex_attrib);
  EXPECT_EQ(a.fragment_attrib, b.fragment_attrib);
  EXPECT_EQ(a.result, b.result);
  EXPECT_EQ(a.state, b.state);
  EXPECT_EQ(a.face, b.face);
  EXPECT_EQ(a.secondary, b.secondary);
  EXPECT_EQ(a.index, b.index);
  EXPECT_EQ(a.coord, b.coord);
  EXPECT_EQ(a.matrix, b.matrix);
  EXPECT_EQ(a.modifier, b.modifier);
  EXPECT_EQ(a.row, b.row);
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_TRUE(SameFloat(a.value[i], b.value[i])) << a.value[i] << " vs " << b.value[i];
  }
}

void ExpectSameSrc(const SrcOperand& a, const SrcOperand& b) {
  EXPECT_EQ(a.var, b.var);
  EXPECT_EQ(a.negate != a.component_negate[0], b.negate != b.component_negate[0]);
  EXPECT_EQ(a.swizzle, b.swizzle);
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(a.negate != a.component_negate[i], b.negate != b.component_negate[i]);
  }
  EXPECT_EQ(a.indexed, b.indexed);
  EXPECT_EQ(a.relative, b.relative);
  EXPECT_EQ(a.address_var, b.address_var);
  EXPECT_EQ(a.address_component, b.address_component);
  EXPECT_EQ(a.abs, b.abs);
  EXPECT_EQ(a.index, b.index);
}

void ExpectSameProgram(const Program& a, const Program& b) {
  EXPECT_EQ(a.kind, b.kind);
  ASSERT_EQ(a.options.size(), b.options.size());
  for (size_t i = 0; i < a.options.size(); ++i) EXPECT_EQ(a.options[i].id, b.options[i].id);
  ASSERT_EQ(a.vars.size(), b.vars.size());
  for (size_t i = 0; i < a.vars.size(); ++i) {
    SCOPED_TRACE("variable " + std::to_string(i) + " '" + a.vars[i].name + "'");
    const Variable& va = a.vars[i];
    const Variable& vb = b.vars[i];
    if (!va.name.empty()) {
      EXPECT_EQ(va.name, vb.name);
    }
    EXPECT_EQ(va.kind, vb.kind);
    EXPECT_EQ(va.size, vb.size);
    EXPECT_EQ(va.is_array, vb.is_array);
    ASSERT_EQ(va.bindings.size(), vb.bindings.size());
    for (size_t k = 0; k < va.bindings.size(); ++k)
      ExpectSameBinding(va.bindings[k], vb.bindings[k]);
  }
  ASSERT_EQ(a.instructions.size(), b.instructions.size());
  for (size_t i = 0; i < a.instructions.size(); ++i) {
    SCOPED_TRACE("instruction " + std::to_string(i));
    const Instruction& ia = a.instructions[i];
    const Instruction& ib = b.instructions[i];
    EXPECT_EQ(ia.op, ib.op);
    EXPECT_EQ(ia.saturate, ib.saturate);
    EXPECT_EQ(ia.signed_saturate, ib.signed_saturate);
    EXPECT_EQ(ia.precision, ib.precision);
    EXPECT_EQ(ia.cc_update, ib.cc_update);
    EXPECT_EQ(ia.jump, ib.jump);
    EXPECT_EQ(ia.label, ib.label);
    for (const auto* cc : {&ia.cond, &ia.dst.cc}) {
      const CcTest& other = cc == &ia.cond ? ib.cond : ib.dst.cc;
      EXPECT_EQ(cc->present, other.present);
      EXPECT_EQ(cc->rule, other.rule);
      EXPECT_EQ(cc->reg, other.reg);
      EXPECT_EQ(cc->swizzle, other.swizzle);
    }
    if (GetOpcodeInfo(ia.op).signature != OpSignature::Kil) {
      EXPECT_EQ(ia.dst.var, ib.dst.var);
      EXPECT_EQ(ia.dst.mask, ib.dst.mask);
    }
    ASSERT_EQ(ia.src_count, ib.src_count);
    for (size_t k = 0; k < ia.src_count; ++k) ExpectSameSrc(ia.src[k], ib.src[k]);
    if (GetOpcodeInfo(ia.op).signature == OpSignature::Sample) {
      EXPECT_EQ(ia.tex_unit, ib.tex_unit);
      EXPECT_EQ(ia.target, ib.target);
    }
  }
}

class PrintTest : public ::testing::TestWithParam<std::string> {};

TEST_P(PrintTest, ParsePrintParseKeepsTheProgram) {
  fs::path path = fs::path(ARBITER_SOURCE_DIR) / "corpus" / "arb" / GetParam();
  std::string log;
  CheckResult first = Check(GetParam(), ReadAll(path), &log);
  ASSERT_TRUE(first.ok) << log;
  std::string printed = PrintProgram(*first.program);
  CheckResult second = Check("printed", printed, &log);
  ASSERT_TRUE(second.ok) << log << "printed:\n" << printed;
  ExpectSameProgram(*first.program, *second.program);
  // Printing is a fixed point after one round.
  EXPECT_EQ(PrintProgram(*second.program), printed);
}

std::string TestName(const ::testing::TestParamInfo<std::string>& info) {
  std::string name;
  for (char c : info.param) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Corpus, PrintTest, ::testing::ValuesIn(ValidFiles()), TestName);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(PrintTest);

TEST(Print, ConstantsKeepEveryBit) {
  std::string log;
  CheckResult r = Check("c.vp",
                        "!!ARBvp1.0\nPARAM c = {0.1, -3.4028235e38, 1.17549435e-38, 16777217};\n"
                        "PARAM d = {1e39, -1e39, -0.0, 1.40129846e-45};\n"
                        "MOV result.position, c;\nMOV result.color, d;\nEND\n",
                        &log);
  ASSERT_TRUE(r.ok) << log;
  std::string printed = PrintProgram(*r.program);
  CheckResult again = Check("printed", printed, &log);
  ASSERT_TRUE(again.ok) << log << printed;
  ExpectSameProgram(*r.program, *again.program);
  EXPECT_TRUE(std::isinf(again.program->vars[1].bindings[0].value[0])) << printed;
}

TEST(Print, NanPrintsAsZero) {
  std::string log;
  CheckResult r =
      Check("n.vp", "!!ARBvp1.0\nPARAM c = {1, 2, 3, 4};\nMOV result.position, c;\nEND\n", &log);
  ASSERT_TRUE(r.ok) << log;
  r.program->vars[0].bindings[0].value[1] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_NE(PrintProgram(*r.program).find("PARAM c = {1, 0, 3, 4};"), std::string::npos)
      << PrintProgram(*r.program);
}

TEST(Print, NegatedSwzSourceFoldsIntoTheComponents) {
  std::string log;
  CheckResult r = Check("s.vp",
                        "!!ARBvp1.0\nTEMP t;\nSWZ t, vertex.position, x, -y, 0, 1;\n"
                        "MOV result.position, t;\nEND\n",
                        &log);
  ASSERT_TRUE(r.ok) << log;
  r.program->instructions[0].src[0].negate = true;
  EXPECT_NE(PrintProgram(*r.program).find(", -x, y, -0, -1;"), std::string::npos)
      << PrintProgram(*r.program);
}

}  // namespace
}  // namespace arbiter::arbvp
