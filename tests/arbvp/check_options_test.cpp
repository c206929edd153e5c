// Tests of OPTION statements: stage, exclusive groups, repetition, unknown names, placement.
#include <string>

#include "check_fixture.h"

namespace arbiter::arbvp {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::IsEmpty;

class CheckOptionRow : public testing::TestWithParam<OptionInfo> {};

// Each option of options.def loads in its own program kind and fails in the other.
TEST_P(CheckOptionRow, AcceptedInItsStageOnly) {
  const OptionInfo& info = GetParam();
  std::string option = "OPTION " + std::string(info.spelling) + ";\n";
  bool for_vp = (static_cast<unsigned>(info.stages) & 1u) != 0;
  bool for_fp = (static_cast<unsigned>(info.stages) & 2u) != 0;
  // Vertex body: result.color only, so that ARB_position_invariant is not violated.
  Checked vp = CheckVp(option + "MOV result.color, vertex.color;\n");
  Checked fp = CheckFp(option + "MOV result.color, fragment.color;\n");
  for (auto [checked, in_stage] : {std::pair{&vp, for_vp}, std::pair{&fp, for_fp}}) {
    if (in_stage) {
      EXPECT_THAT(checked->ErrorKeys(), IsEmpty()) << checked->Dump();
      ASSERT_NE(checked->result.program, nullptr);
      ASSERT_EQ(checked->result.program->options.size(), 1u);
      EXPECT_EQ(checked->result.program->options[0].id, info.id);
    } else {
      EXPECT_THAT(checked->ErrorKeys(), ElementsAre("2:8 arb-option-stage")) << checked->Dump();
      ASSERT_FALSE(checked->Errors().empty());
      EXPECT_THAT(checked->Errors()[0].message,
                  HasSubstr(for_vp ? "for vertex programs only" : "for fragment programs only"));
    }
  }
}

std::string PrintOption(const testing::TestParamInfo<OptionInfo>& param_info) {
  return std::string(param_info.param.spelling);
}

INSTANTIATE_TEST_SUITE_P(OptionsDef, CheckOptionRow, testing::ValuesIn(AllOptions()), PrintOption);

// "Only one fog application option may be specified" (3.11.4.5.1); likewise one precision
// hint (3.11.4.5.2).
TEST(CheckOptions, ExclusiveOptionsConflict) {
  struct Case {
    const char* first;
    const char* second;
    const char* group;
  };
  for (const Case& k :
       {Case{"ARB_fog_linear", "ARB_fog_exp", "fog"}, Case{"ARB_fog_exp", "ARB_fog_exp2", "fog"},
        Case{"ARB_fog_exp2", "ARB_fog_linear", "fog"},
        Case{"ARB_precision_hint_fastest", "ARB_precision_hint_nicest", "precision hint"}}) {
    SCOPED_TRACE(k.second);
    Checked c = CheckFp(std::string("OPTION ") + k.first + ";\nOPTION " + k.second +
                        ";\nMOV result.color, fragment.color;\n");
    EXPECT_THAT(c.ErrorKeys(), ElementsAre("3:8 arb-option-conflict")) << c.Dump();
    ASSERT_FALSE(c.Errors().empty());
    EXPECT_THAT(c.Errors()[0].message,
                HasSubstr(std::string("may specify only one ") + k.group + " option"));
  }
}

TEST(CheckOptions, OptionsOfDifferentGroupsCombine) {
  Checked c = CheckFp(
      "OPTION ARB_fog_exp2;\n"
      "OPTION ARB_precision_hint_nicest;\n"
      "OPTION ARB_fragment_program_shadow;\n"
      "OPTION ARB_draw_buffers;\n"
      "MOV result.color[1], fragment.color;\n");
  EXPECT_THAT(c.ErrorKeys(), IsEmpty()) << c.Dump();
}

// The specs do not forbid naming an option twice: a warning only.
TEST(CheckOptions, RepeatedOptionWarns) {
  Checked c = CheckFp(
      "OPTION ARB_fog_linear;\nOPTION ARB_fog_linear;\nMOV result.color, fragment.color;\n");
  EXPECT_THAT(c.ErrorKeys(), IsEmpty()) << c.Dump();
  EXPECT_THAT(c.WarningKeys(), ElementsAre("3:8 arb-option-repeated"));
  EXPECT_THAT(c.Warnings()[0].message, HasSubstr("given twice"));
  EXPECT_TRUE(c.result.ok);
}

// "A program will fail to load if it specifies a program option not supported by the GL."
TEST(CheckOptions, UnknownOptionIsRejected) {
  Checked typo = CheckFp("OPTION ARB_fog_linaer;\nMOV result.color, fragment.color;\n");
  EXPECT_THAT(typo.ErrorKeys(), ElementsAre("2:8 arb-option-unknown"));
  EXPECT_THAT(typo.Errors()[0].message, HasSubstr("did you mean 'ARB_fog_linear'?"));
  Checked nv = CheckFp("OPTION NV_fragment_program_option;\nMOV result.color, fragment.color;\n");
  EXPECT_THAT(nv.ErrorKeys(), ElementsAre("2:8 arb-option-unknown"));
  // The extension's name is not its option's: the option is NV_fragment_program.
  EXPECT_THAT(nv.Errors()[0].message, HasSubstr("did you mean 'NV_fragment_program'?"));
  Checked other = CheckVp("OPTION MESA_hypothetical;\nMOV result.position, vertex.position;\n");
  EXPECT_THAT(other.ErrorKeys(), ElementsAre("2:8 arb-option-unknown"));
}

// "All program options used by the program must be declared at the beginning of the program
// string." (<program> ::= <optionSequence> <statementSequence> "END")
TEST(CheckOptions, OptionAfterStatementIsRejected) {
  Checked c = CheckFp("MOV result.color, fragment.color;\nOPTION ARB_fog_exp;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("3:1 arb-syntax-option-placement"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("before every other statement"));
  Checked decl = CheckFp("TEMP t;\nOPTION ARB_fog_exp;\n");
  EXPECT_THAT(decl.ErrorKeys(), ElementsAre("3:1 arb-syntax-option-placement"));
}

TEST(CheckOptions, OptionStatementSyntax) {
  Checked no_semicolon = CheckFp("OPTION ARB_fog_exp\nMOV result.color, fragment.color;\n");
  EXPECT_THAT(no_semicolon.ErrorKeys(), ElementsAre("2:19 arb-syntax-missing-semicolon"));
  Checked no_name = CheckFp("OPTION;\nMOV result.color, fragment.color;\n");
  EXPECT_THAT(no_name.ErrorKeys(), ElementsAre("2:7 arb-syntax-expected"));
  EXPECT_THAT(no_name.Errors()[0].message, HasSubstr("an option name"));
}

}  // namespace
}  // namespace arbiter::arbvp
