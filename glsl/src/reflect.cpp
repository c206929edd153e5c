// ReflectShader: a GLSL 1.10 shader's interface, the built-in state it uses and the resources
// it takes, read from glslang's AST (linker objects and a walk of every function).
#include "arbiter/glsl/reflect.h"

#include <fmt/format.h>
#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <set>
#include <string_view>

#include "diag.h"
#include "info_log.h"
#include "prepare.h"
#include "reflect_ast.h"
#include "scan.h"
#include "source_text.h"

namespace arbiter::glsl {
namespace {

using compiler::Range;
using compiler::SourceFile;
using Sources = std::vector<const SourceFile*>;

// As CheckShader: every error, not only the first.
constexpr auto kMessages = static_cast<EShMessages>(EShMsgCascadingErrors);

size_t Index(Stage stage) { return stage == Stage::Vertex ? 0 : 1; }

// ---- Types as GLSL spells them ------------------------------------------------------------

std::string_view BasicName(glslang::TBasicType type) {
  switch (type) {
    case glslang::EbtFloat:
      return "float";
    case glslang::EbtDouble:
      return "double";
    case glslang::EbtInt:
      return "int";
    case glslang::EbtUint:
      return "uint";
    case glslang::EbtBool:
      return "bool";
    default:
      return "void";
  }
}

std::string_view VectorPrefix(glslang::TBasicType type) {
  switch (type) {
    case glslang::EbtDouble:
      return "d";
    case glslang::EbtInt:
      return "i";
    case glslang::EbtUint:
      return "u";
    case glslang::EbtBool:
      return "b";
    default:
      return "";
  }
}

std::string_view DimName(glslang::TSamplerDim dim) {
  switch (dim) {
    case glslang::Esd1D:
      return "1D";
    case glslang::Esd2D:
      return "2D";
    case glslang::Esd3D:
      return "3D";
    case glslang::EsdCube:
      return "Cube";
    case glslang::EsdRect:
      return "2DRect";
    case glslang::EsdBuffer:
      return "Buffer";
    default:
      return "";
  }
}

// sampler2D, samplerCube, sampler2DShadow, sampler2DRect, ...
std::string SamplerName(const glslang::TSampler& sampler) {
  return fmt::format("{}sampler{}{}{}", VectorPrefix(sampler.type), DimName(sampler.dim),
                     sampler.arrayed ? "Array" : "", sampler.shadow ? "Shadow" : "");
}

// The element type (arrays are reported apart): "vec4", "mat3", "mat2x3", "sampler2D", and a
// structure with its members, which decide whether two declarations match.
std::string TypeName(const glslang::TType& type) {
  if (type.getBasicType() == glslang::EbtSampler) return SamplerName(type.getSampler());
  if (type.isStruct()) {
    std::string out = fmt::format("struct {} {{", type.getTypeName().c_str());
    for (const glslang::TTypeLoc& member : *type.getStruct()) {
      out += fmt::format(" {} {}", TypeName(*member.type), member.type->getFieldName().c_str());
      if (member.type->isArray()) out += fmt::format("[{}]", member.type->getOuterArraySize());
      out += ";";
    }
    return out + " }";
  }
  if (type.isMatrix()) {
    std::string_view prefix = type.getBasicType() == glslang::EbtDouble ? "dmat" : "mat";
    if (type.getMatrixCols() == type.getMatrixRows()) {
      return fmt::format("{}{}", prefix, type.getMatrixCols());
    }
    return fmt::format("{}{}x{}", prefix, type.getMatrixCols(), type.getMatrixRows());
  }
  if (type.getVectorSize() > 1) {
    return fmt::format("{}vec{}", VectorPrefix(type.getBasicType()), type.getVectorSize());
  }
  return std::string(BasicName(type.getBasicType()));
}

// The GLSL 1.10 name of a texture lookup (section 8.7): texture2D, texture2DProj,
// shadow2DProj, textureCube, texture2DLod, ...
std::string LookupName(glslang::TOperator op, const glslang::TSampler& sampler) {
  std::string_view suffix;
  switch (op) {
    case glslang::EOpTextureProj:
      suffix = "Proj";
      break;
    case glslang::EOpTextureLod:
      suffix = "Lod";
      break;
    case glslang::EOpTextureProjLod:
      suffix = "ProjLod";
      break;
    case glslang::EOpTextureGrad:
      suffix = "Grad";
      break;
    case glslang::EOpTextureProjGrad:
      suffix = "ProjGrad";
      break;
    default:
      break;
  }
  return fmt::format("{}{}{}", sampler.shadow ? "shadow" : "texture", DimName(sampler.dim), suffix);
}

// ---- Positions ------------------------------------------------------------------------------

// The text with comments and preprocessor lines turned into blanks (offsets and line ends
// kept): where declarations are looked for.
std::string Blanked(std::string_view text) {
  std::string out(text);
  bool line_start = true;
  for (size_t i = 0; i < out.size();) {
    char c = out[i];
    if (c == '\n' || c == '\r') {
      line_start = true;
      ++i;
      continue;
    }
    if (line_start && c == '#') {
      // A directive, with its backslash continuations.
      while (i < out.size() && out[i] != '\n' && out[i] != '\r') {
        if (out[i] == '\\' && i + 1 < out.size() && (out[i + 1] == '\n' || out[i + 1] == '\r')) {
          out[i] = ' ';
          i += 2;
          continue;
        }
        out[i++] = ' ';
      }
      continue;
    }
    if (c != ' ' && c != '\t') line_start = false;
    if (c == '/' && i + 1 < out.size() && out[i + 1] == '/') {
      while (i < out.size() && out[i] != '\n' && out[i] != '\r') out[i++] = ' ';
      continue;
    }
    if (c == '/' && i + 1 < out.size() && out[i + 1] == '*') {
      out[i++] = ' ';
      out[i++] = ' ';
      while (i < out.size() && !(out[i] == '*' && i + 1 < out.size() && out[i + 1] == '/')) {
        if (out[i] != '\n' && out[i] != '\r') out[i] = ' ';
        ++i;
      }
      for (int k = 0; k < 2 && i < out.size(); ++k) out[i++] = ' ';
      continue;
    }
    ++i;
  }
  return out;
}

// Finds where a global is declared: the name in a declaration that starts with its storage
// keyword, outside function bodies. glslang keeps no location for linker objects, so the
// declaration is found in the text; what it declares comes from the AST.
class DeclarationFinder {
 public:
  explicit DeclarationFinder(const Sources& sources) : sources_(sources) {
    for (const SourceFile* file : sources) blanked_.push_back(Blanked(file->text()));
  }

  bool Find(std::string_view keyword, std::string_view name, const SourceFile** file,
            Range* range) const {
    for (size_t s = 0; s < sources_.size(); ++s) {
      const std::string& text = blanked_[s];
      int depth = 0;
      bool in_declaration = false;
      for (size_t i = 0; i < text.size();) {
        char c = text[i];
        if (IsIdentStart(c)) {
          size_t end = i;
          while (end < text.size() && IsIdentChar(text[end])) ++end;
          std::string_view word(text.data() + i, end - i);
          if (depth == 0 && !in_declaration && word == keyword) {
            in_declaration = true;
          } else if (depth == 0 && in_declaration && word == name) {
            *file = sources_[s];
            *range = {static_cast<uint32_t>(i), static_cast<uint32_t>(end)};
            return true;
          }
          i = end;
          continue;
        }
        if (std::isdigit(static_cast<unsigned char>(c))) {
          while (i < text.size() && (IsIdentChar(text[i]) || text[i] == '.')) ++i;
          continue;
        }
        if (c == '{') ++depth;
        if (c == '}' && depth > 0) --depth;
        if (c == ';' && depth == 0) in_declaration = false;
        ++i;
      }
    }
    return false;
  }

 private:
  const Sources& sources_;
  std::vector<std::string> blanked_;
};

// ---- The walk of the code -------------------------------------------------------------------

bool IsAssignment(glslang::TOperator op) {
  return op >= glslang::EOpAssign && op <= glslang::EOpRightShiftAssign;
}

bool IsIncrement(glslang::TOperator op) {
  return op == glslang::EOpPostIncrement || op == glslang::EOpPostDecrement ||
         op == glslang::EOpPreIncrement || op == glslang::EOpPreDecrement;
}

// Operators that select a part of an l-value: indexing, structure fields, swizzles.
bool IsSelector(glslang::TOperator op) {
  return op == glslang::EOpIndexDirect || op == glslang::EOpIndexIndirect ||
         op == glslang::EOpIndexDirectStruct || op == glslang::EOpVectorSwizzle;
}

int ConstantIndex(glslang::TIntermTyped* node) {
  glslang::TIntermConstantUnion* constant = node->getAsConstantUnion();
  return constant != nullptr && constant->getConstArray().size() > 0
             ? constant->getConstArray()[0].getIConst()
             : 0;
}

// The variable an expression designates, through indexing, fields and swizzles.
const glslang::TIntermSymbol* BaseSymbol(glslang::TIntermTyped* node) {
  while (node != nullptr) {
    if (glslang::TIntermSymbol* symbol = node->getAsSymbolNode()) return symbol;
    glslang::TIntermBinary* binary = node->getAsBinaryNode();
    if (binary == nullptr || !IsSelector(binary->getOp())) return nullptr;
    node = binary->getLeft();
  }
  return nullptr;
}

bool IsInterfaceStorage(glslang::TStorageQualifier storage) {
  return storage == glslang::EvqUniform || storage == glslang::EvqVaryingIn ||
         storage == glslang::EvqVaryingOut;
}

// Sizes of the implementation-sized built-in uniform arrays at the GL 2.0 minimums
// (MAX_LIGHTS 8, MAX_CLIP_PLANES 6, MAX_TEXTURE_COORDS 2, MAX_TEXTURE_UNITS 2): glslang
// declares them with its own larger resources; a whole array counts this many elements.
int SpecArraySize(std::string_view name) {
  struct Row {
    std::string_view prefix;
    int size;
  };
  static constexpr Row kRows[] = {
      {"gl_LightSource", 8}, {"gl_FrontLightProduct", 8}, {"gl_BackLightProduct", 8},
      {"gl_ClipPlane", 6},   {"gl_TextureMatrix", 2},     {"gl_EyePlane", 2},
      {"gl_ObjectPlane", 2}, {"gl_TextureEnvColor", 2},
  };
  for (const Row& row : kRows) {
    if (name.substr(0, row.prefix.size()) == row.prefix) return row.size;
  }
  return 0;
}

BuiltinKind KindOf(glslang::TStorageQualifier storage, Stage stage) {
  switch (storage) {
    case glslang::EvqUniform:
      return BuiltinKind::State;
    case glslang::EvqVaryingIn:
      return stage == Stage::Vertex ? BuiltinKind::Attribute : BuiltinKind::Varying;
    case glslang::EvqVaryingOut:
      return BuiltinKind::Varying;
    default:
      return BuiltinKind::Special;
  }
}

// How a user global is used.
struct GlobalUse {
  bool read = false;
  bool written = false;
  std::set<std::string> lookups;
  glslang::TSourceLoc first{};
};

// How one access path of a built-in is used.
struct BuiltinAccess {
  BuiltinKind kind = BuiltinKind::Special;
  int components = 0;
  size_t length = 0;  // of the variable's name, for the range
  bool read = false;
  bool written = false;
  glslang::TSourceLoc first_read{};
  glslang::TSourceLoc first_write{};
};

// Walks the code of a shader, every function (static use: "after pre-processing, the
// shader contains a statement that would write to x, whether or not run-time flow of control
// will cause that statement to be executed", GLSL 1.10 7.2), and records every read and
// write of user globals and built-ins, and texture lookups.
class UseCollector : public glslang::TIntermTraverser {
 public:
  explicit UseCollector(Stage stage) : stage_(stage) {}

  std::map<long long, GlobalUse> globals;         // by symbol id
  std::map<std::string, BuiltinAccess> builtins;  // by access path (sorted)

  void visitSymbol(glslang::TIntermSymbol* symbol) override {
    const glslang::TQualifier& qualifier = symbol->getQualifier();
    bool builtin = symbol->getName().compare(0, 3, "gl_") == 0;
    if (qualifier.storage == glslang::EvqConst) return;
    if (!builtin && !IsInterfaceStorage(qualifier.storage)) return;

    // Climb the selectors whose operand this symbol is; the access path keeps constant array
    // indices and fields, and stops at a variable index, a swizzle or a vector component.
    std::string access(symbol->getName().c_str());
    const glslang::TType* access_type = &symbol->getType();
    bool open = true;
    glslang::TIntermTyped* node = symbol;
    size_t at = path.size();
    while (at > 0) {
      glslang::TIntermBinary* binary = path[at - 1]->getAsBinaryNode();
      if (binary == nullptr || binary->getLeft() != node || !IsSelector(binary->getOp())) break;
      glslang::TOperator op = binary->getOp();
      if (open && op == glslang::EOpIndexDirect && node->getType().isArray()) {
        access += fmt::format("[{}]", ConstantIndex(binary->getRight()));
        access_type = &binary->getType();
      } else if (open && op == glslang::EOpIndexDirectStruct && node->getType().isStruct()) {
        const glslang::TTypeList& members = *node->getType().getStruct();
        auto field = static_cast<size_t>(ConstantIndex(binary->getRight()));
        if (field < members.size()) {
          access += fmt::format(".{}", members[field].type->getFieldName().c_str());
          access_type = &binary->getType();
        } else {
          open = false;
        }
      } else {
        open = false;
      }
      node = binary;
      --at;
    }
    bool read = true;
    bool written = false;
    ClassifyAccess(at > 0 ? path[at - 1] : nullptr, node, &read, &written);

    if (!builtin) {
      GlobalUse& use = globals[symbol->getId()];
      if (!use.read && !use.written) use.first = symbol->getLoc();
      use.read |= read;
      use.written |= written;
      return;
    }
    int components = access_type->computeNumComponents();
    if (access_type == &symbol->getType() && access_type->isArray()) {
      int spec = SpecArraySize(access);
      int size = access_type->getOuterArraySize();
      if (spec > 0 && size > spec) components = components / size * spec;
    }
    Record(access, KindOf(qualifier.storage, stage_), components, symbol->getName().size(),
           symbol->getLoc(), read, written);
  }

  bool visitAggregate(glslang::TVisit visit, glslang::TIntermAggregate* node) override {
    // The linker objects list every declared global: declarations, not uses.
    if (node->getOp() == glslang::EOpLinkerObjects) return false;
    if (visit != glslang::EvPreVisit) return true;
    if (node->isTexture() && !node->getSequence().empty()) {
      glslang::TIntermTyped* sampler = node->getSequence()[0]->getAsTyped();
      const glslang::TIntermSymbol* symbol = sampler ? BaseSymbol(sampler) : nullptr;
      if (symbol != nullptr && symbol->getBasicType() == glslang::EbtSampler) {
        globals[symbol->getId()].lookups.insert(
            LookupName(node->getOp(), symbol->getType().getSampler()));
      }
    }
    if (node->getOp() == glslang::EOpFtransform) {
      // ftransform() is gl_ModelViewProjectionMatrix * gl_Vertex (GLSL 1.10 section 8.5).
      Record("gl_ModelViewProjectionMatrix", BuiltinKind::State, 16, 10, node->getLoc(), true,
             false);
      Record("gl_Vertex", BuiltinKind::Attribute, 4, 10, node->getLoc(), true, false);
    }
    return true;
  }

 private:
  // Whether the expression `node` (a whole l-value) is read, written or both by `parent`.
  static void ClassifyAccess(TIntermNode* parent, glslang::TIntermTyped* node, bool* read,
                             bool* written) {
    if (parent == nullptr) return;
    if (glslang::TIntermBinary* binary = parent->getAsBinaryNode()) {
      if (binary->getLeft() == node && IsAssignment(binary->getOp())) {
        *written = true;
        *read = binary->getOp() != glslang::EOpAssign;
      }
      return;
    }
    if (glslang::TIntermUnary* unary = parent->getAsUnaryNode()) {
      if (IsIncrement(unary->getOp())) *written = true;
      return;
    }
    glslang::TIntermAggregate* call = parent->getAsAggregate();
    if (call == nullptr || call->getOp() != glslang::EOpFunctionCall) return;
    const glslang::TIntermSequence& args = call->getSequence();
    const glslang::TQualifierList& qualifiers = call->getQualifierList();
    for (size_t i = 0; i < args.size() && i < qualifiers.size(); ++i) {
      if (args[i] != node) continue;
      if (qualifiers[i] == glslang::EvqOut) {
        *read = false;
        *written = true;
      } else if (qualifiers[i] == glslang::EvqInOut) {
        *written = true;
      }
    }
  }

  void Record(const std::string& access, BuiltinKind kind, int components, size_t length,
              const glslang::TSourceLoc& loc, bool read, bool written) {
    BuiltinAccess& b = builtins[access];
    b.kind = kind;
    b.components = components;
    b.length = length;
    if (read && !b.read) b.first_read = loc;
    if (written && !b.written) b.first_write = loc;
    b.read |= read;
    b.written |= written;
  }

  Stage stage_;
};

// `name` accesses a part of another access in the list (gl_LightSource[0].diffuse of
// gl_LightSource[0]): counting both would count it twice.
bool Covered(const std::string& name, BuiltinKind kind, const std::vector<BuiltinUse>& list) {
  for (const BuiltinUse& other : list) {
    if (other.kind != kind || other.name.size() >= name.size()) continue;
    if (name.compare(0, other.name.size(), other.name) == 0 &&
        (name[other.name.size()] == '[' || name[other.name.size()] == '.')) {
      return true;
    }
  }
  return false;
}

// Attribute slots of a user attribute (GLSL 1.10 4.3.4): a matN takes N, anything else one.
int AttributeSlots(const ReflectedVariable& v) {
  if (v.type.size() > 3 && v.type.compare(0, 3, "mat") == 0 &&
      std::isdigit(static_cast<unsigned char>(v.type[3]))) {
    return v.type[3] - '0';
  }
  return 1;
}

// The interpolant a built-in varying is: the fragment shader's gl_Color and
// gl_SecondaryColor are the vertex shader's front (or back) colours.
std::string InterpolantKey(const std::string& name, Stage stage) {
  if (stage == Stage::Fragment && name == "gl_Color") return "gl_FrontColor";
  if (stage == Stage::Fragment && name == "gl_SecondaryColor") return "gl_FrontSecondaryColor";
  return name;
}

Contribution Make(std::string key, std::string what, int amount, const SourceFile* file,
                  Range range) {
  return Contribution{std::move(key), std::move(what), amount, file, range};
}

}  // namespace

bool RangeOfLoc(const Sources& sources, const glslang::TSourceLoc& loc, size_t length,
                const SourceFile** file, Range* range) {
  if (loc.string < 0 || static_cast<size_t>(loc.string) >= sources.size() || loc.line < 1) {
    return false;
  }
  const SourceFile* f = sources[static_cast<size_t>(loc.string)];
  if (static_cast<uint32_t>(loc.line) > f->line_count()) return false;
  auto column = static_cast<uint32_t>(loc.column > 0 ? loc.column - 1 : 0);
  std::string_view line = f->LineText(static_cast<uint32_t>(loc.line));
  if (column > line.size()) column = 0;
  uint32_t line_start = f->LineStart(static_cast<uint32_t>(loc.line));
  uint32_t begin = line_start + column;
  auto end = static_cast<uint32_t>(std::min<size_t>(begin + length, line_start + line.size()));
  *file = f;
  *range = {begin, end};
  return true;
}

// A stage's uses, as UseCollector found them.
struct StaticUses {
  std::map<long long, GlobalUse> globals;
  std::map<std::string, BuiltinAccess> builtins;
};

std::string_view StageName(Stage stage) { return stage == Stage::Vertex ? "vertex" : "fragment"; }

bool DefinesMain(TIntermNode* root) {
  glslang::TIntermAggregate* top = root->getAsAggregate();
  if (top == nullptr) return false;
  for (TIntermNode* child : top->getSequence()) {
    glslang::TIntermAggregate* function = child->getAsAggregate();
    if (function != nullptr && function->getOp() == glslang::EOpFunction &&
        function->getName() == "main(") {
      return true;
    }
  }
  return false;
}

// ---- CompiledProgram ------------------------------------------------------------------------

CompiledProgram::CompiledProgram(const Sources& vertex, const Sources& fragment,
                                 const CheckOptions* options)
    : sources_{vertex, fragment} {
  if (options != nullptr) options_ = *options;
  program_ = std::make_unique<glslang::TProgram>();
  bool all = true;
  bool any = false;
  for (Stage stage : {Stage::Vertex, Stage::Fragment}) {
    const Sources& sources = sources_[Index(stage)];
    if (sources.empty()) continue;
    any = true;
    // As CheckShader parses it (its diagnostics were reported there).
    compiler::DiagnosticSink scratch(0);
    PreparedShader prepared = PrepareShader(stage, sources, options_, &scratch);
    if (!prepared.checked) {
      all = false;
      continue;
    }
    bool parsed = false;
    auto shader = ParsePrepared(stage, &prepared, &parsed);
    InfoLogContext log{sources, stage, prepared.version, /*program=*/true, nullptr};
    parsed_[Index(stage)] = parsed || OnlyRelaxedErrors(shader->getInfoLog(), log, /*link=*/false);
    if (parsed_[Index(stage)]) {
      TIntermNode* root = shader->getIntermediate()->getTreeRoot();
      UseCollector collector(stage);
      if (root != nullptr) root->traverse(&collector);
      uses_[Index(stage)] = std::make_unique<StaticUses>(
          StaticUses{std::move(collector.globals), std::move(collector.builtins)});
      program_->addShader(shader.get());
    } else {
      all = false;
    }
    shaders_[Index(stage)] = std::move(shader);
  }
  if (all && any) {
    const Sources& any_sources = sources_[Index(Stage::Fragment)].empty()
                                     ? sources_[Index(Stage::Vertex)]
                                     : sources_[Index(Stage::Fragment)];
    InfoLogContext log{any_sources, Stage::Fragment, 110, /*program=*/true, nullptr};
    linked_ = program_->link(kMessages) || OnlyRelaxedErrors(program_->getInfoLog(), log, true);
  }
}

CompiledProgram::~CompiledProgram() {
  program_.reset();  // before the shaders it refers to
}

bool CompiledProgram::parsed(Stage stage) const { return parsed_[Index(stage)]; }

bool CompiledProgram::HasMain(Stage stage) const {
  if (!parsed(stage)) return false;
  glslang::TIntermediate* ast = shaders_[Index(stage)]->getIntermediate();
  return ast != nullptr && ast->getTreeRoot() != nullptr && DefinesMain(ast->getTreeRoot());
}

const char* CompiledProgram::link_log() const {
  const char* log = program_->getInfoLog();
  return log != nullptr ? log : "";
}

const Sources& CompiledProgram::StageSources(Stage stage) const { return sources_[Index(stage)]; }

bool CompiledProgram::Traverse(Stage stage, glslang::TIntermTraverser* traverser) const {
  if (!parsed(stage)) return false;
  glslang::TIntermediate* ast = shaders_[Index(stage)]->getIntermediate();
  TIntermNode* root = ast != nullptr ? ast->getTreeRoot() : nullptr;
  if (root == nullptr) return false;
  root->traverse(traverser);
  return true;
}

bool CompiledProgram::Reflect(Stage stage, Reflection* out) const {
  const Sources& sources = StageSources(stage);
  out->stage = stage;
  if (!parsed(stage)) return false;
  glslang::TIntermediate* ast = shaders_[Index(stage)]->getIntermediate();
  TIntermNode* root = ast != nullptr ? ast->getTreeRoot() : nullptr;
  if (root == nullptr || !DefinesMain(root)) return false;

  const StaticUses& uses = *uses_[Index(stage)];
  DeclarationFinder declarations(sources);

  // The declared interface, in declaration order: glslang's linker objects.
  for (TIntermNode* child : root->getAsAggregate()->getSequence()) {
    glslang::TIntermAggregate* objects = child->getAsAggregate();
    if (objects == nullptr || objects->getOp() != glslang::EOpLinkerObjects) continue;
    for (TIntermNode* node : objects->getSequence()) {
      glslang::TIntermSymbol* symbol = node->getAsSymbolNode();
      if (symbol == nullptr || symbol->getName().compare(0, 3, "gl_") == 0) continue;
      const glslang::TType& type = symbol->getType();
      glslang::TStorageQualifier storage = type.getQualifier().storage;
      std::vector<ReflectedVariable>* list = nullptr;
      std::string_view keyword;
      if (storage == glslang::EvqUniform) {
        list = type.getBasicType() == glslang::EbtSampler ? &out->samplers : &out->uniforms;
        keyword = "uniform";
      } else if (storage == glslang::EvqVaryingIn && stage == Stage::Vertex) {
        list = &out->attributes;
        keyword = "attribute";
      } else if (storage == glslang::EvqVaryingIn || storage == glslang::EvqVaryingOut) {
        list = &out->varyings;
        keyword = "varying";
      } else {
        continue;
      }
      ReflectedVariable v;
      v.name = RestoreSpelling(symbol->getName().c_str());
      v.type = TypeName(type);
      v.array_size = type.isArray() ? type.getOuterArraySize() : 0;
      v.components = type.computeNumComponents();
      auto use = uses.globals.find(symbol->getId());
      if (use != uses.globals.end()) {
        v.read = use->second.read;
        v.written = use->second.written;
        v.lookups.assign(use->second.lookups.begin(), use->second.lookups.end());
      }
      if (!declarations.Find(keyword, v.name, &v.file, &v.range) && use != uses.globals.end()) {
        RangeOfLoc(sources, use->second.first, v.name.size(), &v.file, &v.range);
      }
      list->push_back(std::move(v));
    }
  }

  for (const auto& [name, access] : uses.builtins) {
    BuiltinUse use;
    use.name = name;
    use.kind = access.kind;
    use.components = access.components;
    if (access.read) {
      RangeOfLoc(sources, access.first_read, access.length, &use.file, &use.range);
      out->builtins_read.push_back(use);
    }
    if (access.written) {
      RangeOfLoc(sources, access.first_write, access.length, &use.file, &use.range);
      out->builtins_written.push_back(use);
    }
  }

  auto sum = [&](Resource resource) {
    int total = 0;
    for (const Contribution& c : Contributions(*out, resource)) total += c.amount;
    return total;
  };
  out->resources.uniform_components = sum(Resource::UniformComponents);
  out->resources.varying_floats = sum(Resource::VaryingFloats);
  out->resources.vertex_attribs = sum(Resource::VertexAttribs);
  out->resources.samplers = sum(Resource::Samplers);
  return true;
}

std::vector<Contribution> Contributions(const Reflection& r, Resource resource) {
  std::vector<Contribution> out;
  bool vertex = r.stage == Stage::Vertex;
  // Built-ins of one kind from one list, each counted once.
  auto builtins = [&](const std::vector<BuiltinUse>& list, BuiltinKind kind, std::string_view what,
                      auto amount) {
    for (const BuiltinUse& b : list) {
      if (b.kind != kind || Covered(b.name, kind, list)) continue;
      if (kind == BuiltinKind::Varying && b.name == "gl_TexCoord") {
        // A whole gl_TexCoord (variably indexed): one interpolant per element.
        for (int i = 0; i < b.components / 4; ++i) {
          out.push_back(Make(fmt::format("gl_TexCoord[{}]", i),
                             fmt::format("{} 'gl_TexCoord[{}]'", what, i), 4, b.file, b.range));
        }
        continue;
      }
      out.push_back(Make(InterpolantKey(b.name, r.stage), fmt::format("{} '{}'", what, b.name),
                         amount(b), b.file, b.range));
    }
  };
  auto components = [](const BuiltinUse& b) { return b.components; };
  switch (resource) {
    case Resource::UniformComponents:
      for (const ReflectedVariable& v : r.uniforms) {
        if (v.read) {
          out.push_back(
              Make(v.name, fmt::format("uniform '{}'", v.name), v.components, v.file, v.range));
        }
      }
      builtins(r.builtins_read, BuiltinKind::State, "built-in uniform", components);
      break;
    case Resource::VaryingFloats:
      for (const ReflectedVariable& v : r.varyings) {
        if (vertex ? v.written : v.read) {
          out.push_back(
              Make(v.name, fmt::format("varying '{}'", v.name), v.components, v.file, v.range));
        }
      }
      builtins(vertex ? r.builtins_written : r.builtins_read, BuiltinKind::Varying,
               "built-in varying", components);
      break;
    case Resource::VertexAttribs:
      if (!vertex) break;
      for (const ReflectedVariable& v : r.attributes) {
        if (v.read) {
          out.push_back(Make(v.name, fmt::format("attribute '{}'", v.name), AttributeSlots(v),
                             v.file, v.range));
        }
      }
      builtins(r.builtins_read, BuiltinKind::Attribute, "built-in attribute",
               [](const BuiltinUse&) { return 1; });
      break;
    case Resource::Samplers:
      for (const ReflectedVariable& v : r.samplers) {
        if (v.read) {
          out.push_back(Make(v.name, fmt::format("sampler '{}'", v.name), std::max(v.array_size, 1),
                             v.file, v.range));
        }
      }
      break;
  }
  return out;
}

Reflection ReflectShader(Stage stage, const Sources& sources, compiler::DiagnosticSink* sink,
                         const CheckOptions& options) {
  Reflection reflection;
  reflection.stage = stage;
  // CheckShader reports every diagnostic (and initialises glslang); the AST comes from a
  // second compile of the same text, which CheckShader does not keep.
  CheckOptions object = options;
  object.link = false;
  if (!CheckShader(stage, sources, object, sink).ok) return reflection;
  Sources none;
  CompiledProgram program(stage == Stage::Vertex ? sources : none,
                          stage == Stage::Fragment ? sources : none, &options);
  if (program.parsed(stage) && !program.linked() && !program.HasMain(stage)) {
    // A shader object without main(): nothing is active until a program links it.
    sink->Report(Info(Diag::LinkMissingMain), sources.front(), {0, 0},
                 "the shader has no main(): info reflects what a shader uses, and a shader "
                 "object without main() uses nothing until a program links it with one");
    return reflection;
  }
  if (!program.linked() || !program.Reflect(stage, &reflection)) {
    sink->Report(Info(Diag::InternalError), sources.front(), {0, 0},
                 "glslang rejected a shader it had accepted; no reflection");
    return reflection;
  }
  reflection.ok = true;
  return reflection;
}

}  // namespace arbiter::glsl
