// GLSL 1.10 chapter 4 (variables, types and qualifiers), where glslang 12 follows later
// versions: varyings of integer, boolean or structure type (4.3.6, allowed from 1.30 on),
// global initializers that are not constant (4.3: "Such initializers must have constant
// type"; later versions allow any expression), and the const initializers glslang does not
// fold (4.3.2; the comma operator, which later versions exclude). Checked from the AST.
#include <fmt/format.h>
#include <glslang/MachineIndependent/localintermediate.h>

#include <algorithm>
#include <cctype>
#include <set>

#include "../frag_coord.h"
#include "../source_text.h"
#include "strict.h"

namespace arbiter::glsl {
namespace {

bool IsVarying(const glslang::TQualifier& q, Stage stage) {
  return stage == Stage::Vertex ? q.storage == glslang::EvqVaryingOut
                                : q.storage == glslang::EvqVaryingIn;
}

// float, vec2..vec4, mat2..mat4 (1.20: any matrix), or arrays of these.
bool IsVaryingType(const glslang::TType& type, int version) {
  if (type.getBasicType() != glslang::EbtFloat) return false;
  if (type.isMatrix()) return version >= 120 || type.getMatrixCols() == type.getMatrixRows();
  return true;
}

// Reports at `name`: at glslang's location when it points there, else at the declaration
// found by `keyword` (glslang's locations of linker objects can be missing).
void Report(const StrictContext& ctx, Diag diag, const glslang::TSourceLoc& loc,
            std::string_view name, std::string_view keyword, std::string message) {
  const compiler::SourceFile* file = ctx.sources.front();
  compiler::Range range{0, 0};
  bool at_loc = RangeOfLoc(ctx, loc, name.size(), &file, &range) &&
                file->text().compare(range.begin, name.size(), name) == 0;
  if (!at_loc && !FindDeclaration(ctx, name, keyword, &file, &range)) {
    file = ctx.sources.front();
    range = {0, 0};
  }
  ctx.sink->Report(Info(diag), file, range, std::move(message));
}

// The built-in functions 1.20 4.3.3 leaves out of constant expressions besides the texture
// lookups (whose sampler is no constant operand anyway).
constexpr glslang::TOperator kNonConstantBuiltins[] = {glslang::EOpNoise, glslang::EOpFtransform};

// Finds a symbol that is not a compile-time constant in an initializer expression.
class NonConstantUse : public glslang::TIntermTraverser {
 public:
  const glslang::TIntermSymbol* found = nullptr;

  const glslang::TIntermAggregate* call = nullptr;    // a user function call
  const glslang::TIntermOperator* builtin = nullptr;  // a call of kNonConstantBuiltins

  // Read-only variables that count as constant too (by glslang symbol id).
  const std::set<long long>* constants = nullptr;

  void visitSymbol(glslang::TIntermSymbol* symbol) override {
    if (found != nullptr || symbol->getQualifier().storage == glslang::EvqConst) return;
    if (constants == nullptr || constants->count(symbol->getId()) == 0) found = symbol;
  }
  bool visitAggregate(glslang::TVisit, glslang::TIntermAggregate* node) override {
    if (node->getOp() == glslang::EOpFunctionCall && call == nullptr) call = node;
    NoteBuiltin(node);
    return true;
  }
  bool visitUnary(glslang::TVisit, glslang::TIntermUnary* node) override {
    NoteBuiltin(node);
    return true;
  }

 private:
  void NoteBuiltin(const glslang::TIntermOperator* node) {
    for (glslang::TOperator op : kNonConstantBuiltins) {
      if (node->getOp() == op && builtin == nullptr) builtin = node;
    }
  }
};

// The name of a call NonConstantUse found: glslang's locations of calls are not the names'.
std::string CalleeName(const glslang::TIntermOperator& call, std::span<const Rename> renames) {
  if (call.getOp() == glslang::EOpNoise) {
    return fmt::format("noise{}", std::max(call.getType().getVectorSize(), 1));
  }
  if (call.getOp() == glslang::EOpFtransform) return "ftransform";
  std::string name = RestoreSpelling(call.getAsAggregate()->getName().c_str(), renames);
  return name.substr(0, name.find('('));
}

std::string_view StorageName(const glslang::TQualifier& q) {
  switch (q.storage) {
    case glslang::EvqUniform:
      return "uniform";
    case glslang::EvqVaryingIn:
    case glslang::EvqVaryingOut:
      return "varying or attribute";
    case glslang::EvqGlobal:
      return "global variable";
    case glslang::EvqConstReadOnly:
      return "const function parameter";
    case glslang::EvqIn:
    case glslang::EvqOut:
    case glslang::EvqInOut:
      return "function parameter";
    default:
      return "non-constant variable";
  }
}

void CheckGlobalInitializers(const StrictContext& ctx, TIntermNode* root) {
  glslang::TIntermAggregate* top = root->getAsAggregate();
  if (top == nullptr) return;
  for (TIntermNode* child : top->getSequence()) {
    glslang::TIntermAggregate* seq = child->getAsAggregate();
    // Global initializers sit in sequences between the function definitions.
    if (seq == nullptr || seq->getOp() != glslang::EOpSequence) continue;
    for (TIntermNode* node : seq->getSequence()) {
      glslang::TIntermBinary* assign = node->getAsBinaryNode();
      if (assign == nullptr || assign->getOp() != glslang::EOpAssign) continue;
      NonConstantUse finder;
      assign->getRight()->traverse(&finder);
      const glslang::TIntermSymbol* target = assign->getLeft()->getAsSymbolNode();
      std::string name = target ? RestoreSpelling(target->getName().c_str()) : "a global";
      if (finder.found == nullptr && finder.call != nullptr) {
        std::string callee = RestoreSpelling(finder.call->getName().c_str(), ctx.renames);
        callee = callee.substr(0, callee.find('('));
        Report(ctx, Diag::GlobalInitializer, finder.call->getLoc(), callee, "=",
               fmt::format("the initializer of global '{}' calls '{}'; GLSL 1.10 says global "
                           "initializers must be constant expressions (1.20 and every driver "
                           "allow it; assign it in main() to be portable)",
                           name, callee));
        continue;
      }
      if (finder.found == nullptr) continue;
      std::string used = RestoreSpelling(finder.found->getName().c_str());
      Report(ctx, Diag::GlobalInitializer, finder.found->getLoc(), used, "=",
             fmt::format("the initializer of global '{}' reads {} '{}'; GLSL 1.10 says global "
                         "initializers must be constant expressions (1.20 and every driver "
                         "allow it; assign it in main() to be portable)",
                         name, StorageName(finder.found->getQualifier()), used));
    }
  }
}

// 4.3.2: "Initializers for const declarations must be formed from literal values, other const
// variables (not including function call parameters), or expressions of these"; 5.9 lists the
// sequence operator (',') among the operators, and 1.20 4.3.3 makes "an expression formed by
// an operator on operands that are all constant expressions" constant. glslang 12 folds no
// comma (as GLSL 4.x), so a local const initialized with one, or with such a const, is only
// read-only to it, its initializer kept (the relaxed "non-constant initializer" of
// info_log.cpp). Its operands are judged here, in declaration order.
class ConstInitializers : public glslang::TIntermTraverser {
 public:
  explicit ConstInitializers(const StrictContext& ctx) : ctx_(ctx) {}

  bool visitBinary(glslang::TVisit, glslang::TIntermBinary* node) override {
    const glslang::TIntermSymbol* target = node->getLeft()->getAsSymbolNode();
    // A read-only variable assigned is a const being initialized: glslang refuses any
    // other assignment to it.
    if (node->getOp() != glslang::EOpAssign || target == nullptr ||
        target->getQualifier().storage != glslang::EvqConstReadOnly) {
      return true;
    }
    Judge(*target, node->getRight());
    read_only_consts_.insert(target->getId());
    return false;
  }

 private:
  void Judge(const glslang::TIntermSymbol& target, TIntermNode* initializer) {
    NonConstantUse finder;
    finder.constants = &read_only_consts_;
    initializer->traverse(&finder);
    const std::string name = RestoreSpelling(target.getName().c_str());
    if (finder.found != nullptr) {
      const std::string used = RestoreSpelling(finder.found->getName().c_str());
      Report(ctx_, Diag::ConstInitializerOperand, finder.found->getLoc(), used, "const",
             fmt::format("the initializer of const '{}' reads {} '{}': {} const initializers "
                         "are formed from literals, const variables other than parameters, "
                         "and expressions of these (section 4.3.2)",
                         name, StorageName(finder.found->getQualifier()), used, VersionName(ctx_)));
      return;
    }
    // 1.10: CheckConstInitializers reports every call of a const initializer, from the text.
    if (ctx_.version == 110) return;
    const glslang::TIntermOperator* call = finder.call;
    if (call == nullptr) call = finder.builtin;
    if (call == nullptr) return;
    const std::string callee = CalleeName(*call, ctx_.renames);
    Report(ctx_, Diag::ConstInitializerCall, call->getLoc(), callee, "const",
           fmt::format("the initializer of const '{}' calls '{}': {} constant expressions call "
                       "no user function, texture lookup, noise function or ftransform "
                       "(section 4.3.3)",
                       name, callee, VersionName(ctx_)));
  }

  const StrictContext& ctx_;
  std::set<long long> read_only_consts_;
};

void CheckVaryingTypes(const StrictContext& ctx, TIntermNode* root) {
  glslang::TIntermAggregate* top = root->getAsAggregate();
  if (top == nullptr) return;
  for (TIntermNode* child : top->getSequence()) {
    glslang::TIntermAggregate* objects = child->getAsAggregate();
    if (objects == nullptr || objects->getOp() != glslang::EOpLinkerObjects) continue;
    for (TIntermNode* node : objects->getSequence()) {
      glslang::TIntermSymbol* symbol = node->getAsSymbolNode();
      if (symbol == nullptr || symbol->getName().compare(0, 3, "gl_") == 0) continue;
      // glslang stores vertex attributes as vertex-stage inputs.
      bool attribute =
          ctx.stage == Stage::Vertex && symbol->getQualifier().storage == glslang::EvqVaryingIn;
      if (!attribute && !IsVarying(symbol->getQualifier(), ctx.stage)) continue;
      if (IsVaryingType(symbol->getType(), ctx.version)) continue;
      std::string name = RestoreSpelling(symbol->getName().c_str());
      std::string_view what = attribute ? "attribute" : "varying";
      Report(ctx, Diag::VaryingType, symbol->getLoc(), name, what,
             fmt::format("{} '{}' has type '{}'; {} {}s are float, vec2, vec3, vec4{}{}", what,
                         name, symbol->getType().getBasicTypeString().c_str(), VersionName(ctx),
                         what, ctx.version >= 120 ? " or matrices" : ", mat2, mat3 or mat4",
                         attribute ? "" : ", or arrays of these"));
    }
  }
}

// ARB_explicit_attrib_location (and ARB_fragment_coord_conventions for gl_FragCoord) put
// layout qualifiers on `in` and `out` declarations: `layout(...) attribute` or `varying` is
// none of them (Mesa: "`layout' qualifier may not be used with `attribute' or `varying'").
// glslang 12 takes it. A layout naming ARB_fragment_coord_conventions' identifiers is judged
// before glslang, with the redeclarations of gl_FragCoord (frag_coord.h).
void CheckLayoutStorage(const StrictContext& ctx) {
  for (const compiler::SourceFile* file : ctx.sources) {
    const std::vector<Token>& tokens = SourceTokens(ctx, file);
    for (size_t i = 0; i + 1 < tokens.size(); ++i) {
      if (tokens[i].text != "layout" || tokens[i + 1].text != "(") continue;
      size_t j = i + 1;
      bool frag_coord = false;  // judged with gl_FragCoord's redeclarations (frag_coord.h)
      for (int depth = 0; j < tokens.size(); ++j) {
        if (tokens[j].text == "(") ++depth;
        if (tokens[j].text == ")" && --depth == 0) break;
        frag_coord = frag_coord || IsFragCoordLayoutId(tokens[j].text);
      }
      if (frag_coord) continue;
      // Other qualifiers (invariant, centroid, flat, ...) may stand between.
      for (++j; j < tokens.size() && tokens[j].kind == Token::Identifier; ++j) {
        std::string_view t = tokens[j].text;
        if (t != "attribute" && t != "varying") continue;
        ctx.sink->Report(Info(Diag::Qualifier), file,
                         {tokens[j].offset, static_cast<uint32_t>(tokens[j].offset + t.size())},
                         fmt::format("a layout qualifier cannot qualify '{}': the extensions "
                                     "that add layout (GL_ARB_explicit_attrib_location, "
                                     "GL_ARB_fragment_coord_conventions) give it to 'in' and "
                                     "'out' declarations",
                                     t));
        break;
      }
    }
  }
}

}  // namespace

void CheckQualifiers(const StrictContext& ctx) {
  CheckLayoutStorage(ctx);
  TIntermNode* root = ctx.ast.getTreeRoot();
  if (root == nullptr) return;
  // EXT_gpu_shader4 allows flat integer varyings; glslang's 1.30 rules check them.
  if (!ctx.gpu4) CheckVaryingTypes(ctx, root);
  // 1.20 drops 1.10's "such initializers must have constant type" (4.3).
  if (ctx.version == 110) CheckGlobalInitializers(ctx, root);
  ConstInitializers const_initializers(ctx);
  root->traverse(&const_initializers);
}

}  // namespace arbiter::glsl
