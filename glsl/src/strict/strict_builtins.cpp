// GLSL 1.10 chapter 7 (built-in variables): "All executions of a well-formed vertex shader
// must write a value into [gl_Position]" (7.1). glslang accepts a vertex shader that never
// writes it; drivers (Mesa) refuse to link one. The spec only allows a diagnostic, so it is
// a warning for a shader and an error when judged as a program. Checked from the AST.
#include <glslang/MachineIndependent/localintermediate.h>

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
  if (ctx.stage != Stage::Vertex || !ctx.linked) return;
  TIntermNode* root = ctx.ast.getTreeRoot();
  if (root == nullptr) return;
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
                   ctx.as_program ? compiler::Severity::Error : compiler::Severity::Warning, file,
                   range,
                   "the vertex shader never writes gl_Position; every execution of a vertex "
                   "shader must write it (GLSL 1.10 section 7.1), and drivers refuse to link "
                   "it into a program");
}

}  // namespace arbiter::glsl
