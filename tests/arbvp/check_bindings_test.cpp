// Tests of bindings: every binding family, matrix rows, selector ranges, attribute aliasing.
#include <string>
#include <vector>

#include "check_fixture.h"

namespace arbiter::arbvp {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::IsEmpty;

const compiler::LimitProfile* SpecMin() { return compiler::BuiltinProfile("spec-min"); }
const compiler::LimitProfile* Mesa() { return compiler::BuiltinProfile("mesa"); }

// A profile with ARB_vertex_blend (4 units) and ARB_matrix_palette (8 matrices).
const compiler::LimitProfile* BlendProfile() {
  static const compiler::LimitProfile profile = [] {
    compiler::LimitProfile p = *compiler::BuiltinProfile("mesa");
    p.name = "blend";
    p.values["arbvp.max_vertex_units"] = 4;
    p.values["arbvp.max_palette_matrices"] = 8;
    return p;
  }();
  return &profile;
}

// ---- every binding form, inline and declared ------------------------------------------

struct BindingCase {
  ProgramKind kind;
  const char* text;       // the binding as written
  const char* canonical;  // BindingName() of what it binds
};

std::string PrintBinding(const testing::TestParamInfo<BindingCase>& info) {
  std::string name = info.param.kind == ProgramKind::Vertex ? "vp_" : "fp_";
  for (const char* p = info.param.text; *p; ++p) {
    char ch = *p;
    bool alnum = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9');
    name += alnum ? ch : '_';
  }
  return name + "_" + std::to_string(info.index);
}

class CheckBindingForms : public testing::TestWithParam<BindingCase> {};

// The binding used directly in an instruction, and in a declaration (ATTRIB, PARAM or
// OUTPUT) whose variable binds what the canonical spelling names.
TEST_P(CheckBindingForms, AcceptedInlineAndDeclared) {
  const BindingCase& p = GetParam();
  std::string text = p.text;
  bool vp = p.kind == ProgramKind::Vertex;
  std::string src = vp ? "vertex.position" : "fragment.color";
  std::string dst = vp ? "result.position" : "result.color";
  std::string position = vp ? "MOV result.position, vertex.position;\n" : "";
  std::string inline_body, declared_body;
  if (text.rfind("result.", 0) == 0) {
    inline_body = "MOV " + text + ", " + src + ";\n" + position;
    declared_body = "OUTPUT v = " + text + ";\nMOV v, " + src + ";\n" + position;
  } else {
    bool attrib = text.rfind("vertex.", 0) == 0 || text.rfind("fragment.", 0) == 0;
    inline_body = "MOV " + dst + ", " + text + ";\n";
    declared_body = (attrib ? "ATTRIB v = " : "PARAM v = ") + text + ";\nMOV " + dst + ", v;\n";
  }
  Checked used = vp ? CheckVp(inline_body) : CheckFp(inline_body);
  EXPECT_THAT(used.diags, IsEmpty()) << inline_body << used.Dump();
  Checked declared = vp ? CheckVp(declared_body) : CheckFp(declared_body);
  EXPECT_THAT(declared.diags, IsEmpty()) << declared_body << declared.Dump();
  ASSERT_NE(declared.result.program, nullptr);
  ASSERT_FALSE(declared.result.program->vars.empty());
  const Variable& v = declared.result.program->vars[0];
  ASSERT_EQ(v.bindings.size(), 1u);
  EXPECT_EQ(BindingName(v.bindings[0], p.kind), p.canonical);
}

constexpr ProgramKind kVp = ProgramKind::Vertex;
constexpr ProgramKind kFp = ProgramKind::Fragment;

INSTANTIATE_TEST_SUITE_P(
    Vertex, CheckBindingForms,
    testing::Values(
        // Table X.2: vertex attributes
        BindingCase{kVp, "vertex.position", "vertex.position"},
        BindingCase{kVp, "vertex.normal", "vertex.normal"},
        BindingCase{kVp, "vertex.color", "vertex.color.primary"},
        BindingCase{kVp, "vertex.color.secondary", "vertex.color.secondary"},
        BindingCase{kVp, "vertex.fogcoord", "vertex.fogcoord"},
        BindingCase{kVp, "vertex.texcoord", "vertex.texcoord[0]"},
        BindingCase{kVp, "vertex.attrib[15]", "vertex.attrib[15]"},
        // Table X.4: results
        BindingCase{kVp, "result.position", "result.position"},
        BindingCase{kVp, "result.color", "result.color.front.primary"},
        BindingCase{kVp, "result.color.back.secondary", "result.color.back.secondary"},
        BindingCase{kVp, "result.fogcoord", "result.fogcoord"},
        BindingCase{kVp, "result.pointsize", "result.pointsize"},
        BindingCase{kVp, "result.texcoord[1]", "result.texcoord[1]"},
        // Table X.3.2: material
        BindingCase{kVp, "state.material.ambient", "state.material.front.ambient"},
        BindingCase{kVp, "state.material.back.shininess", "state.material.back.shininess"},
        // Table X.3.3: lights, light model, light products
        BindingCase{kVp, "state.light[3].position", "state.light[3].position"},
        BindingCase{kVp, "state.light[5].spot.direction", "state.light[5].spot.direction"},
        BindingCase{kVp, "state.light[7].half", "state.light[7].half"},
        BindingCase{kVp, "state.lightmodel.ambient", "state.lightmodel.ambient"},
        BindingCase{kVp, "state.lightmodel.scenecolor", "state.lightmodel.front.scenecolor"},
        BindingCase{kVp, "state.lightmodel.back.scenecolor", "state.lightmodel.back.scenecolor"},
        BindingCase{kVp, "state.lightprod[0].ambient", "state.lightprod[0].front.ambient"},
        BindingCase{kVp, "state.lightprod[7].back.specular", "state.lightprod[7].back.specular"},
        // Table X.3.4-X.3.7: texgen, fog, clip planes, point
        BindingCase{kVp, "state.texgen.eye.s", "state.texgen[0].eye.s"},
        BindingCase{kVp, "state.texgen.object.q", "state.texgen[0].object.q"},
        BindingCase{kVp, "state.fog.color", "state.fog.color"},
        BindingCase{kVp, "state.clip[5].plane", "state.clip[5].plane"},
        BindingCase{kVp, "state.point.size", "state.point.size"},
        BindingCase{kVp, "state.point.attenuation", "state.point.attenuation"},
        // Table X.3.8: matrices, modifiers and rows
        BindingCase{kVp, "state.matrix.modelview.row[0]", "state.matrix.modelview[0].row[0]"},
        BindingCase{kVp, "state.matrix.modelview[0].inverse.row[1]",
                    "state.matrix.modelview[0].inverse.row[1]"},
        BindingCase{kVp, "state.matrix.projection.transpose.row[2]",
                    "state.matrix.projection.transpose.row[2]"},
        BindingCase{kVp, "state.matrix.mvp.invtrans.row[3]", "state.matrix.mvp.invtrans.row[3]"},
        BindingCase{kVp, "state.matrix.texture.row[0]", "state.matrix.texture[0].row[0]"},
        BindingCase{kVp, "state.matrix.texture[1].inverse.row[3]",
                    "state.matrix.texture[1].inverse.row[3]"},
        BindingCase{kVp, "state.matrix.program[7].transpose.row[1]",
                    "state.matrix.program[7].transpose.row[1]"},
        // Table X.3.1 and constants
        BindingCase{kVp, "program.env[0]", "program.env[0]"},
        BindingCase{kVp, "program.local[95]", "program.local[95]"},
        BindingCase{kVp, "{1}", "{1, 0, 0, 1}"}, BindingCase{kVp, "{1, 2, 3}", "{1, 2, 3, 1}"},
        BindingCase{kVp, "{-1, +2, 3.5, -4e1}", "{-1, 2, 3.5, -40}"},
        BindingCase{kVp, "2.5", "{2.5, 2.5, 2.5, 2.5}"}),
    PrintBinding);

INSTANTIATE_TEST_SUITE_P(
    Fragment, CheckBindingForms,
    testing::Values(
        // Table X.1: fragment attributes
        BindingCase{kFp, "fragment.color", "fragment.color.primary"},
        BindingCase{kFp, "fragment.color.secondary", "fragment.color.secondary"},
        BindingCase{kFp, "fragment.texcoord", "fragment.texcoord[0]"},
        BindingCase{kFp, "fragment.fogcoord", "fragment.fogcoord"},
        BindingCase{kFp, "fragment.position", "fragment.position"},
        // Table X.3: results
        BindingCase{kFp, "result.color", "result.color"},
        BindingCase{kFp, "result.depth", "result.depth"},
        // state shared with vertex programs, and the fragment-only items
        BindingCase{kFp, "state.lightprod[2].back.diffuse", "state.lightprod[2].back.diffuse"},
        BindingCase{kFp, "state.texenv.color", "state.texenv[0].color"},
        BindingCase{kFp, "state.texenv[1].color", "state.texenv[1].color"},
        BindingCase{kFp, "state.depth.range", "state.depth.range"},
        BindingCase{kFp, "state.matrix.texture[1].invtrans.row[3]",
                    "state.matrix.texture[1].invtrans.row[3]"},
        BindingCase{kFp, "program.env[23]", "program.env[23]"}),
    PrintBinding);

// ---- unknown bindings and bindings of the other program kind ------------------------------

TEST(CheckBindings, UnknownItemsAreRejected) {
  struct Case {
    const char* text;
    const char* key;
  };
  // Each is used as "MOV result.position, <text>;" (the operand starts at column 22).
  for (const Case& k : {
           Case{"vertex.foo", "2:29 arb-binding-unknown"},
           Case{"state.foo.color", "2:28 arb-binding-unknown"},
           Case{"state.material.front.glow", "2:43 arb-binding-unknown"},
           Case{"state.lightmodel.front.ambient", "2:45 arb-binding-unknown"},
           Case{"state.light[0].spot.angle", "2:42 arb-binding-unknown"},
           Case{"state.texgen[0].eye.u", "2:42 arb-binding-unknown"},
           Case{"state.matrix.view.row[0]", "2:35 arb-binding-unknown"},
           Case{"program.global[0]", "2:30 arb-binding-unknown"},
       }) {
    SCOPED_TRACE(k.text);
    Checked c = CheckVp(std::string("MOV result.position, ") + k.text + ";\n");
    EXPECT_THAT(c.ErrorKeys(), ElementsAre(k.key)) << c.Dump();
  }
}

TEST(CheckBindings, UnknownItemGetsSuggestion) {
  Checked c = CheckFp("MOV result.color, fragment.texcord[0];\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:28 arb-binding-unknown"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("did you mean 'texcoord'?"));
}

TEST(CheckBindings, FragmentBindingsInVertexProgramAreRejected) {
  struct Case {
    const char* body;
    const char* key;
  };
  for (const Case& k : {
           Case{"MOV result.position, fragment.color;\n", "2:22 arb-binding-stage"},
           Case{"MOV result.position, state.texenv.color;\n", "2:28 arb-binding-stage"},
           Case{"PARAM d = state.depth.range;\n", "2:17 arb-binding-stage"},
           Case{"MOV result.depth, vertex.position;\n", "2:12 arb-binding-stage"},
       }) {
    SCOPED_TRACE(k.body);
    Checked c = CheckVp(k.body);
    EXPECT_THAT(c.ErrorKeys(), ElementsAre(k.key)) << c.Dump();
    EXPECT_THAT(c.Errors()[0].message, HasSubstr("fragment"));
  }
}

TEST(CheckBindings, VertexBindingsInFragmentProgramAreRejected) {
  struct Case {
    const char* body;
    const char* key;
  };
  for (const Case& k : {
           Case{"MOV result.color, vertex.position;\n", "2:19 arb-binding-stage"},
           Case{"MOV result.color, state.clip[0].plane;\n", "2:25 arb-binding-stage"},
           Case{"MOV result.color, state.texgen.eye.s;\n", "2:25 arb-binding-stage"},
           Case{"PARAM p = state.point.size;\n", "2:17 arb-binding-stage"},
           Case{"MOV result.position, fragment.position;\n", "2:12 arb-binding-stage"},
           Case{"MOV result.fogcoord, fragment.fogcoord;\n", "2:12 arb-binding-stage"},
           Case{"MOV result.pointsize, fragment.fogcoord;\n", "2:12 arb-binding-stage"},
           Case{"MOV result.texcoord[0], fragment.fogcoord;\n", "2:12 arb-binding-stage"},
           Case{"MOV result.color.back, fragment.color;\n", "2:18 arb-binding-stage"},
           Case{"MOV result.color.secondary, fragment.color;\n", "2:18 arb-binding-stage"},
       }) {
    SCOPED_TRACE(k.body);
    Checked c = CheckFp(k.body);
    EXPECT_THAT(c.ErrorKeys(), ElementsAre(k.key)) << c.Dump();
    EXPECT_THAT(c.Errors()[0].message, HasSubstr("vertex"));
  }
}

// ---- matrices: rows, ranges, whole matrices -------------------------------------------------

TEST(CheckBindings, MatrixRowsBindArrayElements) {
  Checked c = CheckVp(
      "PARAM all[] = { state.matrix.program[0].transpose };\n"
      "PARAM two[2] = { state.matrix.mvp.row[1..2] };\n"
      "PARAM one[] = { state.matrix.projection.row[3] };\n"
      "MOV result.position, all[3];\n"
      "MOV result.color, two[1];\n"
      "MOV result.texcoord, one[0];\n");
  EXPECT_THAT(c.diags, IsEmpty()) << c.Dump();
  ASSERT_NE(c.result.program, nullptr);
  const auto& vars = c.result.program->vars;
  ASSERT_GE(vars.size(), 3u);
  ASSERT_EQ(vars[0].bindings.size(), 4u);
  EXPECT_EQ(BindingName(vars[0].bindings[3], kVp), "state.matrix.program[0].transpose.row[3]");
  ASSERT_EQ(vars[1].bindings.size(), 2u);
  EXPECT_EQ(BindingName(vars[1].bindings[0], kVp), "state.matrix.mvp.row[1]");
  EXPECT_EQ(BindingName(vars[1].bindings[1], kVp), "state.matrix.mvp.row[2]");
  ASSERT_EQ(vars[2].bindings.size(), 1u);
}

// <stateMatrixRowNum> ::= <integer> from 0 to 3
TEST(CheckBindings, MatrixRowBeyondThreeIsRejected) {
  Checked ok = CheckVp("PARAM r = state.matrix.mvp.row[3];\nMOV result.position, r;\n");
  EXPECT_THAT(ok.diags, IsEmpty()) << ok.Dump();
  Checked c = CheckVp("PARAM r = state.matrix.mvp.row[4];\nMOV result.position, r;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:32 arb-binding-index-range"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("rows are numbered 0 to 3"));
}

// "A program will fail to load if <a> is greater than <b>." (ARBvp 2.14.3.2)
TEST(CheckBindings, ReversedRowRangeIsRejected) {
  Checked c = CheckVp("PARAM m[] = { state.matrix.mvp.row[2..1] };\nMOV result.position, m[0];\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:39 arb-binding-row-range"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("[2..1]"));
}

TEST(CheckBindings, ReversedParameterRangeIsRejected) {
  Checked c = CheckFp("PARAM p[] = { program.local[3..1] };\nMOV result.color, p[0];\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:32 arb-binding-row-range"));
}

// <stateSingleItem> takes one row: a whole matrix or a row range needs a PARAM array.
TEST(CheckBindings, WholeMatrixWhereOneVectorExpectedIsRejected) {
  Checked decl = CheckVp("PARAM m = state.matrix.mvp;\n");
  EXPECT_THAT(decl.ErrorKeys(), ElementsAre("2:11 arb-binding-matrix-rows"));
  EXPECT_THAT(decl.Errors()[0].message, HasSubstr("binds 4 rows"));
  Checked range = CheckVp("PARAM m = state.matrix.mvp.row[0..1];\n");
  EXPECT_THAT(range.ErrorKeys(), ElementsAre("2:11 arb-binding-matrix-rows"));
  Checked use = CheckVp("MOV result.position, state.matrix.modelview.inverse;\n");
  EXPECT_THAT(use.ErrorKeys(), ElementsAre("2:22 arb-binding-matrix-rows"));
}

TEST(CheckBindings, ParameterRangeInSingleParamIsRejected) {
  Checked c = CheckVp("PARAM p = program.env[0..3];\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:11 arb-param-array-item"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("can only initialise a PARAM array"));
}

TEST(CheckBindings, HugeSelectorIsRejected) {
  Checked c = CheckFp("MOV result.color, program.env[99999999999];\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:31 arb-binding-index-range"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("too large"));
}

// ---- features the implementation lacks (ARB_vertex_blend, ARB_matrix_palette) -------------

TEST(CheckBindings, BlendAndPaletteBindingsAreUnsupportedInMesa) {
  struct Case {
    const char* body;
    const char* key;
  };
  for (const Case& k : {
           Case{"ATTRIB w = vertex.weight;\n", "2:19 arb-binding-unsupported"},
           Case{"ATTRIB w = vertex.weight[0];\n", "2:19 arb-binding-unsupported"},
           Case{"ATTRIB i = vertex.matrixindex[0];\n", "2:19 arb-binding-unsupported"},
           Case{"PARAM m = state.matrix.modelview[1].row[0];\n", "2:34 arb-binding-unsupported"},
           Case{"PARAM m = state.matrix.palette[0].row[0];\n", "2:24 arb-binding-unsupported"},
       }) {
    SCOPED_TRACE(k.body);
    Checked c = CheckVp(std::string(k.body) + "MOV result.position, vertex.position;\n");
    EXPECT_THAT(c.ErrorKeys(), ElementsAre(k.key)) << c.Dump();
    EXPECT_THAT(c.Errors()[0].message, HasSubstr("does not support"));
  }
}

// "A vertex program will fail to load if a vertex attribute binding specifies a weight number
// <n> that is greater than or equal to MAX_VERTEX_UNITS_ARB or is not divisible by four."
TEST(CheckBindings, WeightNumbersWithVertexBlend) {
  Checked ok = CheckVp(
      "ATTRIB w0 = vertex.weight;\n"
      "ATTRIB i0 = vertex.matrixindex[0];\n"
      "PARAM mv[] = { state.matrix.modelview[3], state.matrix.palette[7] };\n"
      "MOV result.position, w0;\n"
      "MOV result.color, i0;\n"
      "MOV result.texcoord, mv[7];\n",
      BlendProfile());
  EXPECT_THAT(ok.diags, IsEmpty()) << ok.Dump();
  Checked c = CheckVp(
      "ATTRIB w2 = vertex.weight[2];\n"
      "ATTRIB w4 = vertex.weight[4];\n"
      "ATTRIB i5 = vertex.matrixindex[5];\n"
      "PARAM m = state.matrix.modelview[4].row[0];\n"
      "PARAM p = state.matrix.palette[8].row[0];\n",
      BlendProfile());
  EXPECT_THAT(c.ErrorKeys(),
              ElementsAre("2:27 arb-binding-weight-index", "3:27 arb-binding-index-range",
                          "4:32 arb-binding-weight-index", "5:34 arb-binding-index-range",
                          "6:32 arb-binding-index-range"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("multiple of four"));
}

// ---- conventional and generic attribute pairs (ARBvp 2.14.3.1, Table X.2.1) ---------------

struct AliasCase {
  const char* conventional;
  int generic;
  bool needs_blend;  // vertex.weight exists only with ARB_vertex_blend
};

class CheckAttribAlias : public testing::TestWithParam<AliasCase> {};

std::string AliasBody(const std::string& first, const std::string& second) {
  return "ATTRIB a = " + first + ";\nATTRIB b = " + second +
         ";\nMOV result.position, a;\nMOV result.color, b;\n";
}

// Either order is rejected, at the second binding; each of the pair alone is accepted.
TEST_P(CheckAttribAlias, PairIsRejected) {
  const AliasCase& p = GetParam();
  std::string generic = "vertex.attrib[" + std::to_string(p.generic) + "]";
  const compiler::LimitProfile* profile = p.needs_blend ? BlendProfile() : Mesa();
  Checked c = CheckVp(AliasBody(p.conventional, generic), profile);
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("3:12 arb-binding-attrib-alias")) << c.Dump();
  ASSERT_FALSE(c.Errors().empty());
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("'" + generic + "' aliases"));
  Checked reversed = CheckVp(AliasBody(generic, p.conventional), profile);
  EXPECT_THAT(reversed.ErrorKeys(), ElementsAre("3:12 arb-binding-attrib-alias"))
      << reversed.Dump();
  Checked alone1 = CheckVp(AliasBody(p.conventional, "vertex.attrib[6]"), profile);
  EXPECT_THAT(alone1.ErrorKeys(), IsEmpty()) << alone1.Dump();
  Checked alone2 = CheckVp(AliasBody("vertex.attrib[7]", generic), profile);
  EXPECT_THAT(alone2.ErrorKeys(), IsEmpty()) << alone2.Dump();
}

INSTANTIATE_TEST_SUITE_P(
    TableX21, CheckAttribAlias,
    testing::Values(
        AliasCase{"vertex.position", 0, false}, AliasCase{"vertex.weight", 1, true},
        AliasCase{"vertex.weight[0]", 1, true}, AliasCase{"vertex.normal", 2, false},
        AliasCase{"vertex.color", 3, false}, AliasCase{"vertex.color.primary", 3, false},
        AliasCase{"vertex.color.secondary", 4, false}, AliasCase{"vertex.fogcoord", 5, false},
        AliasCase{"vertex.texcoord", 8, false}, AliasCase{"vertex.texcoord[0]", 8, false},
        AliasCase{"vertex.texcoord[1]", 9, false}, AliasCase{"vertex.texcoord[7]", 15, false}));

TEST(CheckBindings, AliasPairInInstructionsIsRejected) {
  Checked c = CheckVp(
      "MOV result.position, vertex.position;\n"
      "MOV result.color, vertex.attrib[0];\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("3:19 arb-binding-attrib-alias"));
}

TEST(CheckBindings, AttributesOfDifferentRowsMayBeMixed) {
  Checked c = CheckVp(
      "ATTRIB t1 = vertex.texcoord[1];\n"
      "ATTRIB g8 = vertex.attrib[8];\n"
      "ATTRIB g1 = vertex.attrib[1];\n"
      "ATTRIB s = vertex.color.secondary;\n"
      "ATTRIB g3 = vertex.attrib[3];\n"
      "MOV result.position, vertex.position;\n"
      "ADD result.color, t1, g8;\n"
      "ADD result.texcoord, g1, s;\n"
      "MOV result.fogcoord, g3;\n");
  EXPECT_THAT(c.diags, IsEmpty()) << c.Dump();
}

// ---- selector ranges against the limit profiles ---------------------------------------------

struct SelectorCase {
  const char* name;
  ProgramKind kind;
  const char* body;  // "{N}" marks the selector
  int within;        // largest selector every implementation takes (spec-min - 1)
  int beyond_min;    // first selector past spec-min, -1 when spec-min equals mesa
  int beyond_mesa;   // first selector past the mesa profile
};

// The body for selector `n`, and the "line:col" of the selector in the program.
std::string Instantiate(const SelectorCase& p, int n, std::string* at) {
  std::string body = p.body;
  size_t pos = body.find("{N}");
  size_t line = 2;
  for (size_t i = 0; i < pos; ++i) line += body[i] == '\n' ? 1 : 0;
  size_t line_start = body.rfind('\n', pos);
  size_t col = pos - (line_start == std::string::npos ? 0 : line_start + 1) + 1;
  *at = std::to_string(line) + ":" + std::to_string(col);
  return body.replace(pos, 3, std::to_string(n));
}

Checked CheckSelector(const SelectorCase& p, int n, const compiler::LimitProfile* profile,
                      std::string* at) {
  std::string body = Instantiate(p, n, at);
  return p.kind == ProgramKind::Vertex ? CheckVp(body, profile) : CheckFp(body, profile);
}

std::string PrintSelector(const testing::TestParamInfo<SelectorCase>& param_info) {
  return param_info.param.name;
}

// The default (Mesa's limits): silent within Mesa's limit, even past spec-min; an error
// past it.
void ExpectDefault(const SelectorCase& p) {
  std::string at;
  Checked within = CheckSelector(p, p.within, nullptr, &at);
  EXPECT_THAT(within.diags, IsEmpty()) << within.Dump();
  if (p.beyond_min >= 0) {
    Checked past_min = CheckSelector(p, p.beyond_min, nullptr, &at);
    EXPECT_THAT(past_min.diags, IsEmpty()) << past_min.Dump();
  }
  Checked failed = CheckSelector(p, p.beyond_mesa, nullptr, &at);
  EXPECT_THAT(failed.ErrorKeys(), ElementsAre(at + " arb-binding-index-range")) << failed.Dump();
  EXPECT_THAT(failed.WarningKeys(), IsEmpty());
  ASSERT_FALSE(failed.Errors().empty());
  EXPECT_THAT(failed.Errors()[0].message, HasSubstr("exceeds the limit"));
  EXPECT_THAT(failed.Errors()[0].message, HasSubstr("in profile 'mesa'"));
}

// An explicit profile is enforced as is.
void ExpectExplicitProfile(const SelectorCase& p) {
  std::string at;
  Checked within = CheckSelector(p, p.within, SpecMin(), &at);
  EXPECT_THAT(within.diags, IsEmpty()) << within.Dump();
  int past_min = p.beyond_min >= 0 ? p.beyond_min : p.beyond_mesa;
  Checked strict = CheckSelector(p, past_min, SpecMin(), &at);
  EXPECT_THAT(strict.ErrorKeys(), ElementsAre(at + " arb-binding-index-range")) << strict.Dump();
  EXPECT_THAT(strict.WarningKeys(), IsEmpty());
  ASSERT_FALSE(strict.Errors().empty());
  EXPECT_THAT(strict.Errors()[0].message, HasSubstr("in profile 'spec-min'"));
  Checked mesa = CheckSelector(p, p.beyond_mesa - 1, Mesa(), &at);
  EXPECT_THAT(mesa.diags, IsEmpty()) << mesa.Dump();
  Checked beyond = CheckSelector(p, p.beyond_mesa, Mesa(), &at);
  EXPECT_THAT(beyond.ErrorKeys(), ElementsAre(at + " arb-binding-index-range")) << beyond.Dump();
}

class CheckSelectorRange : public testing::TestWithParam<SelectorCase> {};

TEST_P(CheckSelectorRange, DefaultAndExplicitProfiles) {
  {
    SCOPED_TRACE("default");
    ExpectDefault(GetParam());
  }
  {
    SCOPED_TRACE("explicit profiles");
    ExpectExplicitProfile(GetParam());
  }
}

INSTANTIATE_TEST_SUITE_P(
    Families, CheckSelectorRange,
    testing::Values(
        SelectorCase{"vertex_texcoord", kVp, "MOV result.position, vertex.texcoord[{N}];\n", 1, 2,
                     8},
        SelectorCase{"vertex_attrib", kVp, "MOV result.position, vertex.attrib[{N}];\n", 15, -1,
                     16},
        SelectorCase{"result_texcoord", kVp,
                     "MOV result.position, vertex.position;\n"
                     "MOV result.texcoord[{N}], vertex.position;\n",
                     1, 2, 8},
        SelectorCase{"light", kVp, "MOV result.position, state.light[{N}].position;\n", 7, -1, 8},
        SelectorCase{"texgen", kVp, "MOV result.position, state.texgen[{N}].object.s;\n", 1, 2, 8},
        SelectorCase{"clip_plane", kVp, "MOV result.position, state.clip[{N}].plane;\n", 5, 6, 8},
        SelectorCase{"vp_texture_matrix", kVp,
                     "MOV result.position, state.matrix.texture[{N}].row[0];\n", 1, 2, 8},
        SelectorCase{"program_matrix", kVp,
                     "MOV result.position, state.matrix.program[{N}].inverse.row[0];\n", 7, -1, 8},
        SelectorCase{"vp_env", kVp, "MOV result.position, program.env[{N}];\n", 95, 96, 256},
        SelectorCase{"fragment_texcoord", kFp, "MOV result.color, fragment.texcoord[{N}];\n", 1, 2,
                     8},
        SelectorCase{"texenv", kFp, "MOV result.color, state.texenv[{N}].color;\n", 1, 2, 8},
        SelectorCase{"fp_texture_matrix", kFp,
                     "MOV result.color, state.matrix.texture[{N}].row[1];\n", 1, 2, 8},
        SelectorCase{"fp_local", kFp, "MOV result.color, program.local[{N}];\n", 23, 24, 2048},
        SelectorCase{"texture_unit", kFp,
                     "TEX result.color, fragment.texcoord[0], texture[{N}], 2D;\n", 1, 2, 32},
        SelectorCase{"draw_buffer", kFp,
                     "OPTION ARB_draw_buffers;\nMOV result.color[{N}], fragment.color;\n", 0, 1,
                     8}),
    PrintSelector);

// A parameter range is checked at its last number.
TEST(CheckBindings, ParameterRangeIsCheckedAtItsEnd) {
  Checked c = CheckVp("PARAM p[] = { program.env[250..256] };\nMOV result.position, p[0];\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:32 arb-binding-index-range"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("program.env parameter 256"));
}

// ARB_draw_buffers: result.color[n] exists only with its option.
TEST(CheckBindings, IndexedResultColorNeedsDrawBuffersOption) {
  Checked c = CheckFp("MOV result.color[1], fragment.color;\n");
  EXPECT_THAT(c.ErrorKeys(), ElementsAre("2:18 arb-option-required"));
  EXPECT_THAT(c.Errors()[0].message, HasSubstr("needs OPTION ARB_draw_buffers"));
}

}  // namespace
}  // namespace arbiter::arbvp
