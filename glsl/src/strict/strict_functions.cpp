// Chapter 6.1 (function definitions), where glslang 12 follows later versions or skips a rule:
// - 1.10 5.8: "non-dereferenced arrays ... cannot be l-values", so an array cannot be an out or
//   inout parameter (1.20 makes arrays first class);
// - 1.20 4.1.7: "Samplers cannot be treated as l-values; hence cannot be used as out or inout
//   function parameters", and they "can only be declared as function parameters or uniform
//   variables" (so no function returns one, in a structure or not). 1.10 says samplers are
//   only function parameters and uniforms, which implies the same; Mesa applies it to both;
// - 1.20 6.1: "Function declarations (prototypes) cannot occur inside of functions; they must
//   be at global scope". glslang accepts them in a function body.
// - 1.20 4.2: "When a function name is redeclared in a nested scope, it hides all functions
//   declared with that name in the outer scope", and the built-ins are in a scope outside the
//   global one (1.10 6.1: once a built-in is redeclared, "the linker will only attempt to
//   resolve that call within the set of shaders"): a shader that declares `exp` cannot call
//   the built-in `exp(float)`. glslang overloads the two.
// The first two are read from the AST's function definitions, the others from the tokens.
#include <fmt/format.h>
#include <glslang/MachineIndependent/localintermediate.h>

#include <set>
#include <string>
#include <utility>

#include "../source_text.h"
#include "strict.h"

namespace arbiter::glsl {
namespace {

// A sampler, or a structure (or array of them) with a sampler among its fields, at any depth.
bool HoldsSampler(const glslang::TType& type) {
  if (type.getBasicType() == glslang::EbtSampler) return true;
  if (type.getBasicType() != glslang::EbtStruct || type.getStruct() == nullptr) return false;
  for (const glslang::TTypeLoc& field : *type.getStruct()) {
    if (HoldsSampler(*field.type)) return true;
  }
  return false;
}

void Report(const StrictContext& ctx, Diag diag, const glslang::TSourceLoc& loc,
            std::string_view name, std::string message) {
  const compiler::SourceFile* file = ctx.sources.front();
  compiler::Range range{0, 0};
  bool at_loc = RangeOfLoc(ctx, loc, name.size(), &file, &range) &&
                file->text().compare(range.begin, name.size(), name) == 0;
  if (!at_loc && !FindDeclaration(ctx, name, "", &file, &range)) {
    file = ctx.sources.front();
    range = {0, 0};
  }
  ctx.sink->Report(Info(diag), file, range, std::move(message));
}

void CheckParameters(const StrictContext& ctx, glslang::TIntermAggregate* function) {
  const std::string function_name = RestoreSpelling(function->getName().c_str(), ctx.renames);
  const std::string short_name = function_name.substr(0, function_name.find('('));
  if (HoldsSampler(function->getType())) {
    Report(ctx, Diag::SamplerUse, function->getLoc(), short_name,
           fmt::format("'{}' returns a {}: samplers can only be uniforms and function "
                       "parameters (GLSL 1.20 section 4.1.7)",
                       short_name,
                       function->getType().getBasicType() == glslang::EbtSampler
                           ? "sampler"
                           : "structure that holds a sampler"));
  }
  for (TIntermNode* child : function->getSequence()) {
    glslang::TIntermAggregate* parameters = child->getAsAggregate();
    if (parameters == nullptr || parameters->getOp() != glslang::EOpParameters) continue;
    for (TIntermNode* node : parameters->getSequence()) {
      glslang::TIntermSymbol* parameter = node->getAsSymbolNode();
      if (parameter == nullptr) continue;
      const glslang::TStorageQualifier storage = parameter->getQualifier().storage;
      if (storage != glslang::EvqOut && storage != glslang::EvqInOut) continue;
      const std::string name = RestoreSpelling(parameter->getName().c_str());
      const char* qualifier = storage == glslang::EvqOut ? "out" : "inout";
      if (HoldsSampler(parameter->getType())) {
        Report(ctx, Diag::SamplerUse, parameter->getLoc(), name,
               fmt::format("parameter '{}' of '{}' is an {} {}: samplers cannot be l-values, so "
                           "not out or inout parameters (GLSL 1.20 section 4.1.7)",
                           name, short_name, qualifier,
                           parameter->getType().getBasicType() == glslang::EbtSampler
                               ? "sampler"
                               : "structure that holds a sampler"));
      } else if (ctx.version == 110 && parameter->getType().isArray()) {
        Report(ctx, Diag::ArrayOperand, parameter->getLoc(), name,
               fmt::format("parameter '{}' of '{}' is an {} array: in GLSL 1.10 arrays are not "
                           "l-values (section 5.8), so not out or inout parameters",
                           name, short_name, qualifier));
      }
    }
  }
}

// 1.20 6.1: a prototype (or definition) inside a function body: `type name (` at the start
// of a statement, where `type` is a built-in type or a structure declared earlier.
void CheckLocalPrototypes(const StrictContext& ctx) {
  static const std::set<std::string_view> kTypes = {
      "void",   "float",  "int",    "bool",   "vec2",   "vec3",   "vec4",  "ivec2",  "ivec3",
      "ivec4",  "bvec2",  "bvec3",  "bvec4",  "mat2",   "mat3",   "mat4",  "mat2x2", "mat2x3",
      "mat2x4", "mat3x2", "mat3x3", "mat3x4", "mat4x2", "mat4x3", "mat4x4"};
  for (size_t index = 0; index < ctx.sources.size(); ++index) {
    const std::vector<Token>& tokens = SourceTokens(ctx, index);
    std::set<std::string_view> structs;
    int depth = 0;
    bool statement_start = true;
    for (size_t i = 0; i < tokens.size(); ++i) {
      std::string_view t = tokens[i].text;
      if (t == "struct" && i + 1 < tokens.size()) structs.insert(tokens[i + 1].text);
      const bool type = kTypes.count(t) > 0 || structs.count(t) > 0;
      if (depth > 0 && statement_start && type && i + 2 < tokens.size() &&
          tokens[i + 1].kind == Token::Identifier && tokens[i + 2].text == "(") {
        const Token& name = tokens[i + 1];
        ctx.sink->Report(
            Info(Diag::LocalFunction), ctx.sources[index],
            {name.offset, static_cast<uint32_t>(name.offset + name.text.size())},
            fmt::format("function '{}' is declared inside a function: function declarations "
                        "must be at global scope (GLSL 1.20 section 6.1)",
                        name.text));
      }
      if (t == "{") ++depth;
      if (t == "}" && depth > 0) --depth;
      statement_start = t == ";" || t == "{" || t == "}";
    }
  }
}

// Collects the lines of calls to user functions, by name ("exp" for "exp(f1;f1;").
class UserCalls : public glslang::TIntermTraverser {
 public:
  std::set<std::pair<std::string, int>> calls;  // (name, line) of each user call
  bool visitAggregate(glslang::TVisit, glslang::TIntermAggregate* node) override {
    if (node->getOp() == glslang::EOpFunctionCall) {
      std::string name = node->getName().c_str();
      calls.emplace(name.substr(0, name.find('(')), node->getLoc().line);
    }
    return true;
  }
};

// The built-in functions of GLSL 1.10 and 1.20 (chapter 8), by name.
bool IsBuiltinFunction(std::string_view name) {
  static const std::set<std::string_view> kNames = {"radians",
                                                    "degrees",
                                                    "sin",
                                                    "cos",
                                                    "tan",
                                                    "asin",
                                                    "acos",
                                                    "atan",
                                                    "pow",
                                                    "exp",
                                                    "log",
                                                    "exp2",
                                                    "log2",
                                                    "sqrt",
                                                    "inversesqrt",
                                                    "abs",
                                                    "sign",
                                                    "floor",
                                                    "ceil",
                                                    "fract",
                                                    "mod",
                                                    "min",
                                                    "max",
                                                    "clamp",
                                                    "mix",
                                                    "step",
                                                    "smoothstep",
                                                    "length",
                                                    "distance",
                                                    "dot",
                                                    "cross",
                                                    "normalize",
                                                    "ftransform",
                                                    "faceforward",
                                                    "reflect",
                                                    "refract",
                                                    "matrixCompMult",
                                                    "outerProduct",
                                                    "transpose",
                                                    "lessThan",
                                                    "lessThanEqual",
                                                    "greaterThan",
                                                    "greaterThanEqual",
                                                    "equal",
                                                    "notEqual",
                                                    "any",
                                                    "all",
                                                    "not",
                                                    "texture1D",
                                                    "texture1DProj",
                                                    "texture1DLod",
                                                    "texture1DProjLod",
                                                    "texture2D",
                                                    "texture2DProj",
                                                    "texture2DLod",
                                                    "texture2DProjLod",
                                                    "texture3D",
                                                    "texture3DProj",
                                                    "texture3DLod",
                                                    "texture3DProjLod",
                                                    "textureCube",
                                                    "textureCubeLod",
                                                    "shadow1D",
                                                    "shadow2D",
                                                    "shadow1DProj",
                                                    "shadow2DProj",
                                                    "shadow1DLod",
                                                    "shadow2DLod",
                                                    "shadow1DProjLod",
                                                    "shadow2DProjLod",
                                                    "dFdx",
                                                    "dFdy",
                                                    "fwidth",
                                                    "noise1",
                                                    "noise2",
                                                    "noise3",
                                                    "noise4"};
  return kNames.count(name) > 0;
}

// Calls of a built-in's name that the shader also declares as a function, which glslang
// resolved to the built-in: no user call of the name on the call's line.
void CheckHiddenBuiltins(const StrictContext& ctx, TIntermNode* root) {
  UserCalls user;
  bool traversed = false;  // the AST walk is paid only by a shader that declares such a name
  for (size_t index = 0; index < ctx.sources.size(); ++index) {
    const compiler::SourceFile* file = ctx.sources[index];
    const std::vector<Token>& tokens = SourceTokens(ctx, file);
    std::set<std::string_view> declared;  // functions the shader declares at global scope
    int depth = 0;
    for (size_t i = 0; i + 2 < tokens.size(); ++i) {
      if (tokens[i].text == "{") ++depth;
      if (tokens[i].text == "}" && depth > 0) --depth;
      if (depth == 0 && tokens[i].kind == Token::Identifier &&
          tokens[i + 1].kind == Token::Identifier && tokens[i + 2].text == "(" &&
          tokens[i].text != "return" && IsBuiltinFunction(tokens[i + 1].text)) {
        declared.insert(tokens[i + 1].text);
      }
    }
    if (declared.empty()) continue;
    if (!traversed) root->traverse(&user);
    traversed = true;
    depth = 0;
    for (size_t i = 0; i + 1 < tokens.size(); ++i) {
      if (tokens[i].text == "{") ++depth;
      if (tokens[i].text == "}" && depth > 0) --depth;
      const Token& t = tokens[i];
      // `type name (` in a body is a local prototype (CheckLocalPrototypes), not a call.
      const bool declaration =
          i > 0 && tokens[i - 1].kind == Token::Identifier && tokens[i - 1].text != "return";
      if (depth == 0 || t.kind != Token::Identifier || tokens[i + 1].text != "(" ||
          declared.count(t.text) == 0 || declaration) {
        continue;
      }
      const compiler::LineCol at = file->Locate(t.offset);
      // glslang's string numbering is the sources' index: a user call is on this line.
      if (user.calls.count({std::string(t.text), static_cast<int>(at.line)}) > 0) continue;
      ctx.sink->Report(Info(Diag::NoMatchingFunction), file,
                       {t.offset, static_cast<uint32_t>(t.offset + t.text.size())},
                       fmt::format("no function '{}' of the shader matches this call, and the "
                                   "shader's '{}' hides the built-in functions of that name "
                                   "(GLSL 1.20 section 4.2; 1.10 section 6.1)",
                                   t.text, t.text));
    }
  }
}

}  // namespace

void CheckFunctions(const StrictContext& ctx) {
  if (ctx.version >= 120) CheckLocalPrototypes(ctx);
  TIntermNode* root = ctx.ast.getTreeRoot();
  glslang::TIntermAggregate* top = root != nullptr ? root->getAsAggregate() : nullptr;
  if (top == nullptr) return;
  for (TIntermNode* child : top->getSequence()) {
    glslang::TIntermAggregate* function = child->getAsAggregate();
    if (function != nullptr && function->getOp() == glslang::EOpFunction) {
      CheckParameters(ctx, function);
    }
  }
  CheckHiddenBuiltins(ctx, root);
}

}  // namespace arbiter::glsl
