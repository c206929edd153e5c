// The operand of a unary '+' (GLSL 1.10 and 1.20, 5.9): the arithmetic unary operators
// "operate on integer or floating-point values (including vectors and matrices)", and 5.7 lists
// the only operators that take arrays and structures whole, '+' not among them. glslang 12
// drops a unary '+' while parsing (it builds no node for it), so `+f()` of a void f, `+a` of an
// array or a structure and `+b` of a bool pass it. The '+' tokens are found in the text and
// their operand in the AST: a name or a call with no postfix operator after it, whose node
// starts where the operand's first token is.
#include <fmt/format.h>
#include <glslang/MachineIndependent/localintermediate.h>

#include <set>
#include <string>
#include <utility>

#include "strict.h"

namespace arbiter::glsl {
namespace {

bool Touch(const Token& a, const Token& b) { return a.offset + a.text.size() == b.offset; }

bool IsPunct(const Token& t, char c) { return t.kind == Token::Punct && t.text[0] == c; }

// Words after which an operand begins rather than ends.
bool IsOperandStartWord(std::string_view word) { return word == "return"; }

// The index past the ')' matching the '(' at `open`, or tokens.size().
size_t SkipParens(const std::vector<Token>& tokens, size_t open) {
  int depth = 0;
  for (size_t i = open; i < tokens.size(); ++i) {
    if (IsPunct(tokens[i], '(')) ++depth;
    if (IsPunct(tokens[i], ')') && --depth == 0) return i + 1;
  }
  return tokens.size();
}

// Whether tokens[i] starts a postfix operator: [ . ( ++ --.
bool IsPostfix(const std::vector<Token>& tokens, size_t i) {
  if (i >= tokens.size()) return false;
  const Token& t = tokens[i];
  if (IsPunct(t, '[') || IsPunct(t, '.') || IsPunct(t, '(')) return true;
  return (IsPunct(t, '+') || IsPunct(t, '-')) && i + 1 < tokens.size() &&
         tokens[i + 1].text == t.text && Touch(t, tokens[i + 1]);
}

using Operands = std::set<std::pair<const compiler::SourceFile*, uint32_t>>;

// The offsets of the names and calls that are the whole operand of a unary '+' in `tokens`.
void FindOperands(const compiler::SourceFile* file, const std::vector<Token>& tokens,
                  Operands* names, Operands* calls) {
  bool operand_ended = false;  // the previous token ends an operand: a '+' now is binary
  for (size_t i = 0; i < tokens.size(); ++i) {
    const Token& t = tokens[i];
    bool doubled = i + 1 < tokens.size() && tokens[i + 1].text == t.text && Touch(t, tokens[i + 1]);
    if ((IsPunct(t, '+') || IsPunct(t, '-')) && doubled) {  // ++ or --: postfix keeps the end
      ++i;
      continue;
    }
    if (IsPunct(t, '+') && !operand_ended &&
        !(i + 1 < tokens.size() && IsPunct(tokens[i + 1], '=') && Touch(t, tokens[i + 1]))) {
      size_t at = i + 1;
      if (at < tokens.size() && tokens[at].kind == Token::Identifier) {
        bool call = at + 1 < tokens.size() && IsPunct(tokens[at + 1], '(');
        size_t after = call ? SkipParens(tokens, at + 1) : at + 1;
        if (!IsPostfix(tokens, after)) {
          (call ? calls : names)->insert({file, tokens[at].offset});
          // glslang places a call at its name, its '(' or its ')'.
          if (call) {
            calls->insert({file, tokens[at + 1].offset});
            calls->insert({file, tokens[after - 1].offset});
          }
        }
      }
    }
    operand_ended = (t.kind == Token::Identifier && !IsOperandStartWord(t.text)) ||
                    t.kind == Token::Number || IsPunct(t, ')') || IsPunct(t, ']');
  }
}

bool IsNumber(const glslang::TType& type) {
  if (type.isArray()) return false;
  switch (type.getBasicType()) {
    case glslang::EbtFloat:
    case glslang::EbtInt:
    case glslang::EbtUint:
      return true;
    default:
      return false;
  }
}

std::string Describe(const glslang::TType& type) {
  if (type.isArray()) return "an array";
  if (type.getBasicType() == glslang::EbtVoid) return "a call of a void function";
  if (type.getBasicType() == glslang::EbtStruct) return "a structure";
  return fmt::format("a {}", type.getBasicTypeString().c_str());
}

class UnaryPlusOperands : public glslang::TIntermTraverser {
 public:
  UnaryPlusOperands(const StrictContext& ctx, const Operands& names, const Operands& calls)
      : ctx_(ctx), names_(names), calls_(calls) {}

  void visitSymbol(glslang::TIntermSymbol* node) override { Judge(node, names_); }

  bool visitAggregate(glslang::TVisit, glslang::TIntermAggregate* node) override {
    if (node->getOp() == glslang::EOpFunctionCall) Judge(node, calls_);
    return true;
  }

 private:
  void Judge(glslang::TIntermTyped* node, const Operands& operands) {
    if (IsNumber(node->getType())) return;
    const compiler::SourceFile* file = nullptr;
    compiler::Range range;
    if (!RangeOfLoc(ctx_, node->getLoc(), 1, &file, &range)) return;
    if (operands.count({file, range.begin}) == 0 || !reported_.insert({file, range.begin}).second)
      return;
    // The '+' itself: the last '+' before the operand.
    std::string_view text = file->text();
    uint32_t plus = range.begin;
    while (plus > 0 && text[plus] != '+') --plus;
    ctx_.sink->Report(Info(Diag::UnaryPlusOperand), file, {plus, plus + 1},
                      fmt::format("unary '+' takes an integer or floating-point scalar, vector "
                                  "or matrix (section 5.9); its operand is {}",
                                  Describe(node->getType())));
  }

  const StrictContext& ctx_;
  const Operands& names_;
  const Operands& calls_;
  Operands reported_;
};

}  // namespace

void CheckUnaryPlus(const StrictContext& ctx) {
  Operands names;
  Operands calls;
  for (size_t i = 0; i < ctx.sources.size(); ++i) {
    FindOperands(ctx.sources[i], SourceTokens(ctx, i), &names, &calls);
  }
  TIntermNode* root = ctx.ast.getTreeRoot();
  if ((names.empty() && calls.empty()) || root == nullptr) return;
  UnaryPlusOperands rules(ctx, names, calls);
  root->traverse(&rules);
}

}  // namespace arbiter::glsl
