// GLSL 1.10 chapter 5 (operators and expressions), where glslang 12 follows later versions.
// Checked from the AST:
// - whole arrays as operands: 5.7 "[ ] ... is the only operator that operates on arrays";
//   5.8 "non-dereferenced arrays ... cannot be l-values"; 5.9 "The equality operators ...
//   operate on all types except arrays" and the ?: operands "can be of any type other than an
//   array". glslang allows them from 1.20 on; its 1.10 errors for '=' and '==' also hit
//   structures with array fields, which 1.10 allows, so info_log.cpp drops those and this
//   rule decides.
// - the third operand of ?:: chapter 9 "conditional_expression : logical_or_expression
//   QUESTION expression COLON conditional_expression". glslang parses an
//   assignment_expression there, so it reads `p ? a : b = c` as `p ? a : (b = c)`, where 1.10
//   reads `(p ? a : b) = c`: an assignment to a ?:, which 5.8 says is not an l-value.
#include <fmt/format.h>
#include <glslang/MachineIndependent/localintermediate.h>

#include <string_view>

#include "strict.h"

namespace arbiter::glsl {
namespace {

bool IsAssignment(glslang::TOperator op) {
  return op >= glslang::EOpAssign && op <= glslang::EOpRightShiftAssign;
}

// The byte offset of a glslang location in its source string; false when it is not there.
bool OffsetOf(const StrictContext& ctx, const glslang::TSourceLoc& loc,
              const compiler::SourceFile** file, uint32_t* offset) {
  compiler::Range range;
  if (!RangeOfLoc(ctx, loc, 1, file, &range)) return false;
  *offset = range.begin;
  return true;
}

// Whether the operator at `op` (the assignment in the third operand of the ?: at `question`)
// is inside parentheses opened after the ':' of that ?:. Comments are skipped; a text that
// does not have the ?: where glslang says (macros) counts as parenthesized.
bool Parenthesized(std::string_view text, uint32_t question, uint32_t op) {
  if (question >= op || op >= text.size() || text[question] != '?') return true;
  int depth = 0;   // ( and [ since '?'
  int nested = 0;  // unmatched '?' since '?'
  bool after_colon = false;
  int depth_at_colon = 0;
  for (uint32_t i = question + 1; i < op; ++i) {
    if (text.substr(i, 2) == "//") {
      while (i < op && text[i] != '\n') ++i;
      continue;
    }
    if (text.substr(i, 2) == "/*") {
      size_t end = text.find("*/", i + 2);
      if (end == std::string_view::npos || end >= op) return true;
      i = static_cast<uint32_t>(end + 1);
      continue;
    }
    char c = text[i];
    if (c == '(' || c == '[') ++depth;
    if (c == ')' || c == ']') --depth;
    if (after_colon) continue;
    if (c == '?') ++nested;
    if (c == ':' && depth == 0 && nested-- == 0) {
      after_colon = true;
      depth_at_colon = depth;
    }
  }
  return !after_colon || depth > depth_at_colon;
}

class ExpressionRules : public glslang::TIntermTraverser {
 public:
  explicit ExpressionRules(const StrictContext& ctx) : ctx_(ctx) {}

  bool visitBinary(glslang::TVisit, glslang::TIntermBinary* node) override {
    glslang::TOperator op = node->getOp();
    if (IsAssignment(op) && node->getLeft()->getType().isArray()) {
      Report(Diag::ArrayOperand, node->getLoc(), 1,
             "a whole array cannot be assigned in GLSL 1.10: arrays are not l-values "
             "(section 5.8); assign its elements one by one");
    } else if ((op == glslang::EOpEqual || op == glslang::EOpNotEqual) &&
               (node->getLeft()->getType().isArray() || node->getRight()->getType().isArray())) {
      Report(Diag::ArrayOperand, node->getLoc(), 2,
             fmt::format("whole arrays cannot be compared with '{}' in GLSL 1.10: the equality "
                         "operators work on all types except arrays (section 5.9)",
                         op == glslang::EOpEqual ? "==" : "!="));
    }
    return true;
  }

  bool visitSelection(glslang::TVisit, glslang::TIntermSelection* node) override {
    if (node->getType().getBasicType() == glslang::EbtVoid) return true;  // an if statement
    if (node->getType().isArray()) {
      Report(Diag::ArrayOperand, node->getLoc(), 1,
             "the operands of '?:' cannot be arrays in GLSL 1.10 (section 5.9); select an "
             "element instead");
    }
    glslang::TIntermTyped* third =
        node->getFalseBlock() != nullptr ? node->getFalseBlock()->getAsTyped() : nullptr;
    glslang::TIntermBinary* assign = third != nullptr ? third->getAsBinaryNode() : nullptr;
    if (assign != nullptr && IsAssignment(assign->getOp())) CheckThirdOperand(node, assign);
    return true;
  }

 private:
  void CheckThirdOperand(glslang::TIntermSelection* node, glslang::TIntermBinary* assign) {
    const compiler::SourceFile* file = nullptr;
    const compiler::SourceFile* op_file = nullptr;
    uint32_t question = 0;
    uint32_t op = 0;
    if (!OffsetOf(ctx_, node->getLoc(), &file, &question) ||
        !OffsetOf(ctx_, assign->getLoc(), &op_file, &op) || file != op_file ||
        Parenthesized(file->text(), question, op)) {
      return;
    }
    Report(Diag::ConditionalAssignment, assign->getLoc(), 1,
           "GLSL 1.10 reads 'a ? b : c = d' as '(a ? b : c) = d': the third operand of '?:' "
           "is a conditional expression (chapter 9 grammar), and '?:' is not an l-value "
           "(section 5.8); put the assignment in parentheses");
  }

  void Report(Diag diag, const glslang::TSourceLoc& loc, size_t length, std::string message) {
    const compiler::SourceFile* file = ctx_.sources.front();
    compiler::Range range{0, 0};
    if (!RangeOfLoc(ctx_, loc, length, &file, &range)) {
      file = ctx_.sources.front();
      range = {0, 0};
    }
    ctx_.sink->Report(Info(diag), file, range, std::move(message));
  }

  const StrictContext& ctx_;
};

}  // namespace

void CheckExpressions(const StrictContext& ctx) {
  // 1.20 makes arrays first-class (5.7-5.9) and its grammar takes an assignment_expression
  // as the third operand of '?:' (chapter 9).
  if (ctx.version != 110) return;
  TIntermNode* root = ctx.ast.getTreeRoot();
  if (root == nullptr) return;
  ExpressionRules rules(ctx);
  root->traverse(&rules);
}

}  // namespace arbiter::glsl
