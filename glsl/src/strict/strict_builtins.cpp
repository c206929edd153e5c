// GLSL 1.10 chapter 7 (built-in variables), checked from the AST:
// - 7.1: "All executions of a well-formed vertex shader must write a value into
//   [gl_Position]". glslang accepts a vertex shader that never writes it; drivers (Mesa)
//   refuse to link one. The spec only allows a diagnostic, so it is a warning for a shader
//   and an error when judged as a program.
// - 7.2: "If a shader statically assigns a value to gl_FragColor, it may not assign a value
//   to any element of gl_FragData". glslang's link step rejects any use of both, reads
//   included (info_log.cpp drops that message); this rule counts assignments.
// - 7.6: "varying vec4 gl_TexCoord[]; // at most will be gl_MaxTextureCoords". glslang sizes
//   the unsized array from its largest constant index without bounding it.
#include <fmt/format.h>
#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>

#include "../reflect_ast.h"
#include "strict.h"

namespace arbiter::glsl {
namespace {

// The variable an l-value expression ends in: through indexing, swizzles and fields.
const glslang::TIntermSymbol* BaseSymbol(glslang::TIntermTyped* node) {
  while (node != nullptr) {
    if (glslang::TIntermSymbol* symbol = node->getAsSymbolNode()) return symbol;
    glslang::TIntermBinary* binary = node->getAsBinaryNode();
    if (binary == nullptr) return nullptr;
    switch (binary->getOp()) {
      case glslang::EOpIndexDirect:
      case glslang::EOpIndexIndirect:
      case glslang::EOpIndexDirectStruct:
      case glslang::EOpVectorSwizzle:
        node = binary->getLeft();
        break;
      default:
        return nullptr;
    }
  }
  return nullptr;
}

bool IsPosition(glslang::TIntermTyped* node) {
  const glslang::TIntermSymbol* symbol = BaseSymbol(node);
  return symbol != nullptr && symbol->getName() == "gl_Position";
}

bool IsAssignment(glslang::TOperator op) {
  return op >= glslang::EOpAssign && op <= glslang::EOpRightShiftAssign;
}

// Assignments to gl_FragColor and gl_FragData, as such or through an out or inout argument
// of a user function, and constant gl_TexCoord indices past gl_MaxTextureCoords.
class BuiltinUses : public glslang::TIntermTraverser {
 public:
  explicit BuiltinUses(const StrictContext& ctx) : ctx_(ctx) {}

  bool visitBinary(glslang::TVisit, glslang::TIntermBinary* node) override {
    if (IsAssignment(node->getOp())) Written(node->getLeft());
    if (node->getOp() == glslang::EOpIndexDirect) CheckTexCoordIndex(node);
    return true;
  }

  bool visitAggregate(glslang::TVisit, glslang::TIntermAggregate* node) override {
    if (node->getOp() != glslang::EOpFunctionCall) return true;
    const glslang::TQualifierList& qualifiers = node->getQualifierList();
    for (size_t i = 0; i < node->getSequence().size(); ++i) {
      glslang::TIntermTyped* arg = node->getSequence()[i]->getAsTyped();
      bool out = i >= qualifiers.size() || qualifiers[i] == glslang::EvqOut ||
                 qualifiers[i] == glslang::EvqInOut;
      if (arg != nullptr && out) Written(arg);
    }
    return true;
  }

 private:
  void Written(glslang::TIntermTyped* target) {
    const glslang::TIntermSymbol* symbol = BaseSymbol(target);
    if (symbol == nullptr) return;
    FragmentOutputWrites& writes = *ctx_.fragment_writes;
    if (symbol->getName() == "gl_FragColor") writes.color = true;
    if (symbol->getName() == "gl_FragData" && !writes.data) {
      writes.data = true;
      RangeOfLoc(ctx_, symbol->getLoc(), std::string_view("gl_FragData").size(), &writes.data_file,
                 &writes.data_range);
    }
  }

  void CheckTexCoordIndex(glslang::TIntermBinary* node) {
    const glslang::TIntermSymbol* array = node->getLeft()->getAsSymbolNode();
    const glslang::TIntermConstantUnion* index = node->getRight()->getAsConstantUnion();
    if (array == nullptr || index == nullptr || array->getName() != "gl_TexCoord") return;
    int max = GetDefaultResources()->maxTextureCoords;
    int value = index->getConstArray()[0].getIConst();
    if (value < max) return;
    const compiler::SourceFile* file = ctx_.sources.front();
    compiler::Range range{0, 0};
    // glslang places the index node at the index expression.
    if (!RangeOfLoc(ctx_, node->getLoc(), 1, &file, &range)) {
      file = ctx_.sources.front();
      range = {0, 0};
    }
    ctx_.sink->Report(Info(Diag::TexCoordIndex), file, range,
                      fmt::format("gl_TexCoord index {} is past the last texture coordinate "
                                  "set: gl_TexCoord has at most gl_MaxTextureCoords ({}) "
                                  "elements ({} section 7.6)",
                                  value, max, VersionName(ctx_)));
  }

  const StrictContext& ctx_;
};

// Finds any write of gl_Position: an assignment, or an argument of a user function (which
// may be an out parameter; counted as a write, erring towards acceptance).
class PositionWrites : public glslang::TIntermTraverser {
 public:
  bool written = false;

  bool visitBinary(glslang::TVisit, glslang::TIntermBinary* node) override {
    if (node->getOp() >= glslang::EOpAssign && node->getOp() <= glslang::EOpRightShiftAssign &&
        IsPosition(node->getLeft())) {
      written = true;
    }
    return !written;
  }

  bool visitAggregate(glslang::TVisit, glslang::TIntermAggregate* node) override {
    if (node->getOp() == glslang::EOpFunctionCall) {
      for (TIntermNode* arg : node->getSequence()) {
        glslang::TIntermTyped* typed = arg->getAsTyped();
        if (typed != nullptr && IsPosition(typed)) written = true;
      }
    }
    return !written;
  }
};

}  // namespace

void CheckBuiltinVariables(const StrictContext& ctx) {
  TIntermNode* root = ctx.ast.getTreeRoot();
  if (root == nullptr) return;
  BuiltinUses uses(ctx);
  root->traverse(&uses);
}

void CheckFragmentOutputs(const StrictContext& ctx) {
  const FragmentOutputWrites& writes = *ctx.fragment_writes;
  // A compile error in drivers (Mesa), where glslang reports it at link time only.
  if (ctx.stage != Stage::Fragment || !writes.color || !writes.data) return;
  const compiler::SourceFile* file = writes.data_file;
  if (file == nullptr) file = ctx.sources.front();
  ctx.sink->Report(Info(Diag::LinkFragColorAndData), file, writes.data_range,
                   "cannot use both gl_FragColor and gl_FragData");
}

void CheckPositionWritten(const StrictContext& ctx) {
  if (ctx.stage != Stage::Vertex || (ctx.link && !ctx.linked)) return;
  TIntermNode* root = ctx.ast.getTreeRoot();
  if (root == nullptr) return;
  // A shader object without main() may leave gl_Position to another one.
  if (!ctx.link && !DefinesMain(root)) return;
  PositionWrites finder;
  root->traverse(&finder);
  if (finder.written) return;
  // Point at main's definition when it can be found, else at the start of the shader.
  const compiler::SourceFile* file = ctx.sources.front();
  compiler::Range range{0, 0};
  if (!FindDeclaration(ctx, "main", "void", &file, &range)) {
    file = ctx.sources.front();
    range = {0, 0};
  }
  ctx.sink->Report(Info(Diag::PositionUnwritten),
                   ctx.link ? compiler::Severity::Error : compiler::Severity::Warning, file, range,
                   fmt::format("the vertex shader never writes gl_Position; every execution of a "
                               "vertex shader must write it ({} section 7.1), and drivers "
                               "refuse to link it into a program",
                               VersionName(ctx)));
}

}  // namespace arbiter::glsl
