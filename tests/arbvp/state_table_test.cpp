// Tests of the state-item table (glstate/state_items.def) against the parser and the
// printer: every item, matrix and modifier spelled as the table says parses back to itself,
// and a group is refused in the program kind that lacks it.
#include <string>
#include <vector>

#include "check_fixture.h"

namespace arbiter::arbvp {
namespace {

using ::testing::ElementsAre;
using ::testing::IsEmpty;

// A table spelling with its fields filled: selector 1, the back face, coordinate t.
std::string Spell(std::string_view spelling, std::string_view matrix = "") {
  std::string out;
  for (size_t i = 0; i < spelling.size(); ++i) {
    if (spelling[i] != '{') {
      out.push_back(spelling[i]);
      continue;
    }
    const char field = spelling[i + 1];
    i += 2;
    out += field == 'i'   ? "1"
           : field == 'f' ? "back"
           : field == 'c' ? "t"
           : field == 'r' ? "2"
                          : matrix;
  }
  return out;
}

// The state binding of `PARAM p = <binding>;` in a program of the given kind.
Checked CheckParam(ProgramKind kind, const std::string& binding) {
  std::string body = "PARAM p = " + binding + ";\n";
  body += kind == ProgramKind::Vertex ? "MOV result.position, p;\n" : "MOV result.color, p;\n";
  return kind == ProgramKind::Vertex ? CheckVp(body) : CheckFp(body);
}

const Binding* ParamBinding(const Checked& c) {
  if (!c.result.program) return nullptr;
  for (const Variable& v : c.result.program->vars) {
    if (v.name == "p" && !v.bindings.empty()) return &v.bindings[0];
  }
  return nullptr;
}

TEST(StateTable, EveryItemParsesToItselfAndPrintsItsSpelling) {
  for (const glstate::StateItemInfo& info : glstate::kStateItems) {
    if (info.item == StateItem::MatrixRow) continue;
    const glstate::StateGroupInfo* group = glstate::FindStateGroup(info.group);
    ASSERT_NE(group, nullptr) << info.group;
    for (ProgramKind kind : {ProgramKind::Vertex, ProgramKind::Fragment}) {
      const std::string spelled = Spell(info.spelling);
      SCOPED_TRACE(spelled);
      Checked c = CheckParam(kind, spelled);
      if (!glstate::GroupInStage(*group, kind == ProgramKind::Vertex)) {
        EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:17 arb-binding-stage")) << c.Dump();
        continue;
      }
      EXPECT_THAT(c.ErrorKeys(), IsEmpty()) << c.Dump();
      const Binding* b = ParamBinding(c);
      ASSERT_NE(b, nullptr);
      EXPECT_EQ(b->state, info.item);
      EXPECT_EQ(BindingName(*b, kind), spelled);
    }
  }
}

TEST(StateTable, EveryMatrixAndModifierParsesToItself) {
  const std::vector<std::pair<std::string, MatrixModifier>> modifiers = {
      {"", MatrixModifier::None},
      {".inverse", MatrixModifier::Inverse},
      {".transpose", MatrixModifier::Transpose},
      {".invtrans", MatrixModifier::InvTrans}};
  const glstate::StateItemInfo& row = glstate::GetStateItemInfo(StateItem::MatrixRow);
  for (const glstate::StateMatrixInfo& matrix : glstate::kStateMatrices) {
    for (const auto& [suffix, modifier] : modifiers) {
      const std::string spelled = Spell(row.spelling, Spell(matrix.spelling) + suffix);
      SCOPED_TRACE(spelled);
      // Palette matrices need ARB_matrix_palette, and modelview[1] ARB_vertex_blend, which
      // Mesa's limits lack: the parse is what is tested here.
      Checked c = CheckParam(ProgramKind::Vertex, spelled);
      const Binding* b = ParamBinding(c);
      ASSERT_NE(b, nullptr) << c.Dump();
      EXPECT_EQ(b->state, StateItem::MatrixRow);
      EXPECT_EQ(b->matrix, matrix.matrix);
      EXPECT_EQ(b->modifier, modifier);
      EXPECT_EQ(b->row, 2);
      EXPECT_EQ(b->index, matrix.index == glstate::MatrixIndex::No ? 0 : 1);
      EXPECT_EQ(BindingName(*b, ProgramKind::Vertex), spelled);
    }
  }
}

// A selector the table marks required cannot be left out; an optional one is 0.
TEST(StateTable, SelectorsAsTheTableSays) {
  EXPECT_THAT(CheckParam(ProgramKind::Vertex, "state.light.ambient").ErrorKeys(),
              ElementsAre("2:22 arb-syntax-expected"));
  EXPECT_THAT(CheckParam(ProgramKind::Vertex, "state.clip.plane").ErrorKeys(),
              ElementsAre("2:21 arb-syntax-expected"));
  Checked texgen = CheckParam(ProgramKind::Vertex, "state.texgen.object.q");
  EXPECT_THAT(texgen.ErrorKeys(), IsEmpty()) << texgen.Dump();
  ASSERT_NE(ParamBinding(texgen), nullptr);
  EXPECT_EQ(ParamBinding(texgen)->index, 0);
  EXPECT_EQ(ParamBinding(texgen)->coord, 3);
  // A face only where the item takes one: lightmodel.ambient has none.
  EXPECT_THAT(CheckParam(ProgramKind::Vertex, "state.lightmodel.front.ambient").ErrorKeys(),
              ElementsAre("2:34 arb-binding-unknown"));
}

}  // namespace
}  // namespace arbiter::arbvp
