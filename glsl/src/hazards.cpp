// FindHazards: the operations glslang's AST holds whose result GLSL leaves undefined for some
// operands, located at their operator or function name (hazards.h).
#include "arbiter/glsl/hazards.h"

#include <glslang/Include/intermediate.h>

#include <algorithm>
#include <cctype>
#include <utility>

#include "reflect_ast.h"

namespace arbiter::glsl {
namespace {

// A built-in function call by glslang operator. glslang places a call at one of its
// arguments, not at the function's name: the name is found as the innermost call of it
// whose parentheses hold that place.
struct CallKind {
  glslang::TOperator op;
  HazardKind kind;
  std::string_view name;  // "proj" and "cube": the lookups of kProjNames and kCubeNames
};
constexpr CallKind kCalls[] = {
    {glslang::EOpMod, HazardKind::Mod, "mod"},
    {glslang::EOpPow, HazardKind::Pow, "pow"},
    {glslang::EOpLog, HazardKind::Log, "log"},
    {glslang::EOpLog2, HazardKind::Log, "log2"},
    {glslang::EOpSqrt, HazardKind::Sqrt, "sqrt"},
    {glslang::EOpInverseSqrt, HazardKind::InverseSqrt, "inversesqrt"},
    {glslang::EOpAsin, HazardKind::AsinAcos, "asin"},
    {glslang::EOpAcos, HazardKind::AsinAcos, "acos"},
    {glslang::EOpNormalize, HazardKind::Normalize, "normalize"},
    {glslang::EOpClamp, HazardKind::Clamp, "clamp"},
    {glslang::EOpSmoothStep, HazardKind::Smoothstep, "smoothstep"},
};
// atan(y, x): an aggregate EOpAtan (atan(y_over_x) is unary, and defined everywhere).
constexpr CallKind kAtan2 = {glslang::EOpAtan, HazardKind::Atan, "atan"};
constexpr CallKind kLookups[] = {
    {glslang::EOpTextureProj, HazardKind::Projection, "proj"},
    {glslang::EOpTextureProjLod, HazardKind::Projection, "proj"},
    {glslang::EOpTexture, HazardKind::CubeFace, "cube"},
    {glslang::EOpTextureLod, HazardKind::CubeFace, "cube"},
};
constexpr std::string_view kCubeNames[] = {"textureCube", "textureCubeLod"};
constexpr std::string_view kProjNames[] = {
    "texture1DProj",   "texture2DProj",    "texture3DProj",     "shadow1DProj",
    "shadow2DProj",    "texture1DProjLod", "texture2DProjLod",  "texture3DProjLod",
    "shadow1DProjLod", "shadow2DProjLod",  "texture2DRectProj", "shadow2DRectProj"};

bool NameIs(std::string_view found, std::string_view name) {
  if (name == "proj") {
    return std::find(std::begin(kProjNames), std::end(kProjNames), found) != std::end(kProjNames);
  }
  if (name == "cube") {
    return std::find(std::begin(kCubeNames), std::end(kCubeNames), found) != std::end(kCubeNames);
  }
  return found == name;
}

bool SamplesCube(glslang::TIntermAggregate* node) {
  const glslang::TIntermSequence& args = node->getSequence();
  if (args.empty() || args[0]->getAsTyped() == nullptr) return false;
  const glslang::TType& type = args[0]->getAsTyped()->getType();
  return type.getBasicType() == glslang::EbtSampler && type.getSampler().dim == glslang::EsdCube;
}

bool IsIdentChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

// The range of `name` in the innermost call `name(...)` whose parentheses hold byte `at`;
// false when there is none within a few lines before it.
bool EnclosingCall(std::string_view text, uint32_t at, std::string_view name,
                   compiler::Range* range) {
  constexpr uint32_t kReach = 4096;
  const uint32_t stop = at > kReach ? at - kReach : 0;
  for (uint32_t i = std::min<uint32_t>(at, static_cast<uint32_t>(text.size())); i-- > stop;) {
    if (text[i] != '(') continue;
    uint32_t end = i;
    while (end > 0 && (text[end - 1] == ' ' || text[end - 1] == '\t')) --end;
    uint32_t begin = end;
    while (begin > 0 && IsIdentChar(text[begin - 1])) --begin;
    if (!NameIs(text.substr(begin, end - begin), name)) continue;
    int depth = 0;
    uint32_t close = i;
    for (; close < text.size(); ++close) {
      if (text[close] == '(') ++depth;
      if (text[close] == ')' && --depth == 0) break;
    }
    if (close < at) continue;  // a call that ends before `at` does not hold it
    *range = {begin, end};
    return true;
  }
  return false;
}

// The elements an index into `type` selects among (0 when unknown: unsized arrays).
int IndexedSize(const glslang::TType& type) {
  if (type.isArray()) return type.isSizedArray() ? type.getOuterArraySize() : 0;
  if (type.isMatrix()) return type.getMatrixCols();
  if (type.isVector()) return type.getVectorSize();
  return 0;
}

class HazardCollector : public glslang::TIntermTraverser {
 public:
  explicit HazardCollector(const std::vector<const compiler::SourceFile*>& sources)
      : sources_(sources) {}

  std::vector<Hazard> hazards;

  bool visitBinary(glslang::TVisit /*visit*/, glslang::TIntermBinary* node) override {
    switch (node->getOp()) {
      case glslang::EOpDiv:
        Add(HazardKind::Division, node->getLoc(), 1, false, 0);
        break;
      case glslang::EOpDivAssign:
        Add(HazardKind::Division, node->getLoc(), 2, true, 0);
        break;
      case glslang::EOpIndexIndirect: {
        const int size = IndexedSize(node->getLeft()->getType());
        if (size > 0) Add(HazardKind::Index, node->getLoc(), 1, false, size);
        break;
      }
      default:
        break;
    }
    return true;
  }

  bool visitUnary(glslang::TVisit /*visit*/, glslang::TIntermUnary* node) override {
    for (const CallKind& c : kCalls) {
      if (c.op == node->getOp()) Call(c, node->getLoc());
    }
    return true;
  }

  bool visitAggregate(glslang::TVisit /*visit*/, glslang::TIntermAggregate* node) override {
    if (node->getOp() == glslang::EOpLinkerObjects) return false;
    if (node->getOp() == kAtan2.op) Call(kAtan2, node->getLoc());
    for (const CallKind& c : kLookups) {
      if (c.op != node->getOp()) continue;
      if (c.kind == HazardKind::CubeFace && !SamplesCube(node)) continue;
      Call(c, node->getLoc());
    }
    for (const CallKind& c : kCalls) {
      if (c.op == node->getOp()) Call(c, node->getLoc());
    }
    return true;
  }

 private:
  void Call(const CallKind& c, const glslang::TSourceLoc& loc) {
    Hazard h;
    h.kind = c.kind;
    if (!RangeOfLoc(sources_, loc, 1, &h.file, &h.range) ||
        !EnclosingCall(h.file->text(), h.range.begin, c.name, &h.range)) {
      h.file = nullptr;
    }
    hazards.push_back(h);
  }

  void Add(HazardKind kind, const glslang::TSourceLoc& loc, size_t length, bool compound,
           int size) {
    Hazard h;
    h.kind = kind;
    h.compound = compound;
    h.size = size;
    if (!RangeOfLoc(sources_, loc, length, &h.file, &h.range)) h.file = nullptr;
    hazards.push_back(h);
  }

  const std::vector<const compiler::SourceFile*>& sources_;
};

}  // namespace

const std::vector<HazardInfo>& AllHazards() {
  static const std::vector<HazardInfo> kInfo = {
#define ARBITER_GLSL_HAZARD_INFO(name, what, spec) {HazardKind::name, #name, what, spec},
      ARBITER_GLSL_HAZARDS(ARBITER_GLSL_HAZARD_INFO)
#undef ARBITER_GLSL_HAZARD_INFO
  };
  return kInfo;
}

const HazardInfo& GetHazardInfo(HazardKind kind) { return AllHazards()[static_cast<size_t>(kind)]; }

std::vector<Hazard> FindHazards(Stage stage,
                                const std::vector<const compiler::SourceFile*>& sources,
                                const CheckOptions& options) {
  const std::vector<const compiler::SourceFile*> none;
  const bool vertex = stage == Stage::Vertex;
  CompiledProgram program(vertex ? sources : none, vertex ? none : sources, &options);
  HazardCollector collector(program.StageSources(stage));
  if (!program.Traverse(stage, &collector)) return {};
  std::vector<Hazard> out = std::move(collector.hazards);
  const std::vector<const compiler::SourceFile*>& in = program.StageSources(stage);
  auto order = [&in](const Hazard& h) {  // unplaced ones last
    auto at = static_cast<size_t>(std::find(in.begin(), in.end(), h.file) - in.begin());
    return std::make_pair(at, h.range.begin);
  };
  std::stable_sort(out.begin(), out.end(),
                   [&](const Hazard& a, const Hazard& b) { return order(a) < order(b); });
  return out;
}

}  // namespace arbiter::glsl
