// LowerForVulkan: GLSL 1.10/1.20 to Vulkan GLSL 4.50 over glslang's preprocessed text, one
// token at a time (scan.h), with the tables of builtins.h. See lower_vulkan.h.
#include "arbiter/glsl/lower_vulkan.h"

#include <fmt/format.h>
#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <algorithm>
#include <map>
#include <memory>
#include <set>

#include "extensions.h"
#include "lower/builtins.h"
#include "prepare.h"
#include "scan.h"
#include "source_text.h"

namespace arbiter::glsl {
namespace {

using lower::BuiltinRole;
using lower::BuiltinVariable;

std::string Refusal(std::string_view construct) {
  return fmt::format("not applicable: {}", construct);
}

// glslang's preprocessed text of the shader, with the directives arbiter reads first (#version,
// #extension) and the preamble Mesa's implicit extensions bring; empty with `refusal` or
// `error` set when the shader is one the lowering does not take.
bool Preprocess(Stage stage, std::string_view text, std::string* out, int* version,
                std::map<std::string, int>* implicit_sizes, std::string* refusal) {
  EnsureGlslang();
  compiler::SourceFile file("<shader>", std::string(text));
  compiler::DiagnosticSink scratch(0);
  PreparedShader prepared = PrepareShader(stage, {&file}, CheckOptions{}, &scratch);
  if (!prepared.checked || scratch.error_count() > 0) {
    *refusal = Refusal("a shader arbiter's checker does not accept");
    return false;
  }
  if (prepared.gpu4()) {
    *refusal = Refusal(prepared.gpu_shader4 ? "GL_EXT_gpu_shader4" : "GL_EXT_texture_array");
    return false;
  }
  *version = prepared.version;
  if (prepared.include) {
    *refusal = Refusal("#include (GL_ARB_shading_language_include)");
    return false;
  }
  // The sizes glslang gives the uniform arrays declared without one (GLSL 1.10 4.1.9: the
  // largest constant index used, plus one), by the shader's names.
  bool parsed = false;
  std::unique_ptr<glslang::TShader> ast = ParsePrepared(stage, &prepared, &parsed);
  if (parsed && ast->getIntermediate()->getTreeRoot() != nullptr) {
    const glslang::TIntermAggregate* root = ast->getIntermediate()->getTreeRoot()->getAsAggregate();
    const glslang::TIntermSequence none;
    for (TIntermNode* node : root != nullptr ? root->getSequence() : none) {
      const glslang::TIntermAggregate* objects = node->getAsAggregate();
      if (objects == nullptr || objects->getOp() != glslang::EOpLinkerObjects) continue;
      for (TIntermNode* object : objects->getSequence()) {
        const glslang::TIntermSymbol* symbol = object->getAsSymbolNode();
        if (symbol == nullptr || symbol->getQualifier().storage != glslang::EvqUniform ||
            !symbol->getType().isUnsizedArray()) {
          continue;
        }
        (*implicit_sizes)[RestoreSpelling(symbol->getName().c_str(), prepared.renames)] =
            symbol->getType().getImplicitArraySize();
      }
    }
  }
  std::vector<const char*> strings;
  std::vector<int> lengths;
  for (const std::string& t : prepared.texts) {
    strings.push_back(t.data());
    lengths.push_back(static_cast<int>(t.size()));
  }
  glslang::TShader shader(stage == Stage::Vertex ? EShLangVertex : EShLangFragment);
  shader.setStringsWithLengths(strings.data(), lengths.data(), static_cast<int>(strings.size()));
  if (!prepared.preamble.empty()) shader.setPreamble(prepared.preamble.c_str());
  glslang::TShader::ForbidIncluder includer;
  if (!shader.preprocess(GetDefaultResources(), 110, ENoProfile, false, false, EShMsgDefault, out,
                         includer)) {
    *refusal = Refusal("a shader glslang's preprocessor rejects");
    return false;
  }
  return true;
}

// An extension whose enabling changes nothing in the lowered text: "all" (only warnings),
// GL_ARB_draw_buffers (gl_FragData is 1.10's own), GL_ARB_texture_rectangle (its samplers
// are refused where used), and what Mesa does not have (enabling it enables nothing).
bool ChangesNothing(std::string_view extension) {
  const Extension* known = FindExtension(extension);
  return extension == "all" || extension == "GL_ARB_draw_buffers" ||
         extension == "GL_ARB_texture_rectangle" || known == nullptr || !known->mesa;
}

struct Lowering {
  Stage stage;
  int version;
  std::map<std::string, int> implicit_sizes;  // uniform arrays declared without a size
  std::string out;
  std::string refusal;
  std::set<std::string> state;    // built-in uniforms used
  std::set<std::string> structs;  // built-in structure types needed
  std::set<std::string> shadow;   // samplers of shadow lookups (user names)
  bool shadow_helper = false;
};

bool Refuse(Lowering* l, std::string_view construct) {
  if (l->refusal.empty()) l->refusal = Refusal(construct);
  return false;
}

// A built-in name of the shader: its lowered spelling, recording what it needs.
bool LowerBuiltin(Lowering* l, std::string_view name, std::string* spelled) {
  if (lower::FindBuiltinStruct(name) != nullptr) {
    l->structs.insert(std::string(name));
    *spelled = LoweredIdentifier(name);
    return true;
  }
  const BuiltinVariable* v = lower::FindBuiltinVariable(name);
  const uint8_t mask = l->stage == Stage::Vertex ? lower::Vertex : lower::Fragment;
  if (v == nullptr || (v->stages & mask) == 0) return Refuse(l, std::string(name));
  if (v->role == BuiltinRole::Keep) {
    *spelled = std::string(name);
    return true;
  }
  if (v->role == BuiltinRole::State) {
    l->state.insert(std::string(name));
    if (!v->type_name.empty()) l->structs.insert(std::string(v->type_name));
  }
  *spelled = LoweredIdentifier(name);
  return true;
}

// The index just past the ')' that closes the '(' at `open`; tokens.size() if none.
size_t Closing(const std::vector<Token>& tokens, size_t open) {
  int depth = 0;
  for (size_t i = open; i < tokens.size(); ++i) {
    if (tokens[i].text == "(") ++depth;
    if (tokens[i].text == ")" && --depth == 0) return i;
  }
  return tokens.size();
}

// The end (index of ';') of the statement that starts at `i`.
size_t StatementEnd(const std::vector<Token>& tokens, size_t i) {
  while (i < tokens.size() && tokens[i].text != ";") ++i;
  return i;
}

// The declarations the lowered text starts with: built-in structures, uniforms, globals,
// constants and the shadow helper.
std::string Declarations(const Lowering& l) {
  std::string out = "#version 450\n";
  for (const std::string& s : l.structs) {
    out += fmt::format("struct {} {{ {} }};\n", LoweredIdentifier(s),
                       lower::FindBuiltinStruct(s)->members);
  }
  for (const std::string& name : l.state) {
    const BuiltinVariable* v = lower::FindBuiltinVariable(name);
    out += fmt::format("uniform {} {}{};\n", v->type, LoweredIdentifier(name),
                       v->array_size > 0 ? fmt::format("[{}]", v->array_size) : "");
  }
  return out;
}

std::string Globals(Stage stage) {
  std::string out;
  const uint8_t mask = stage == Stage::Vertex ? lower::Vertex : lower::Fragment;
  for (std::string_view name : {"gl_Vertex",
                                "gl_Normal",
                                "gl_Color",
                                "gl_SecondaryColor",
                                "gl_MultiTexCoord0",
                                "gl_MultiTexCoord1",
                                "gl_MultiTexCoord2",
                                "gl_MultiTexCoord3",
                                "gl_MultiTexCoord4",
                                "gl_MultiTexCoord5",
                                "gl_MultiTexCoord6",
                                "gl_MultiTexCoord7",
                                "gl_FogCoord",
                                "gl_Position",
                                "gl_PointSize",
                                "gl_ClipVertex",
                                "gl_FrontColor",
                                "gl_BackColor",
                                "gl_FrontSecondaryColor",
                                "gl_BackSecondaryColor",
                                "gl_TexCoord",
                                "gl_FogFragCoord",
                                "gl_FragCoord",
                                "gl_FragColor",
                                "gl_FragData",
                                "gl_FragDepth",
                                "gl_MaxLights",
                                "gl_MaxClipPlanes",
                                "gl_MaxTextureUnits",
                                "gl_MaxTextureCoords",
                                "gl_MaxVertexAttribs",
                                "gl_MaxDrawBuffers"}) {
    const BuiltinVariable* v = lower::FindBuiltinVariable(name);
    if ((v->stages & mask) == 0) continue;
    if (v->role == BuiltinRole::Const) {
      out += fmt::format("const int {} = {};\n", LoweredIdentifier(name), v->value);
    } else {
      out += fmt::format("{} {}{};\n", v->type, LoweredIdentifier(name),
                         v->array_size > 0 ? fmt::format("[{}]", v->array_size) : "");
    }
  }
  return out;
}

// GL_DEPTH_TEXTURE_MODE applied to a shadow lookup's result r: per component, selector 0
// reads 0, 1 reads r, 2 reads 1 (glstate::DepthModeSelector).
constexpr std::string_view kShadowHelper =
    "float arb_depth_part(float r, float s) { return s < 0.5 ? 0.0 : (s < 1.5 ? r : 1.0); }\n"
    "vec4 arb_shadow(float r, vec4 s) {\n"
    "  return vec4(arb_depth_part(r, s.x), arb_depth_part(r, s.y), arb_depth_part(r, s.z),\n"
    "              arb_depth_part(r, s.w));\n"
    "}\n";

// Rewrites the code (directives blanked) of `text`.
bool Rewrite(std::string_view code, Lowering* l) {
  const std::vector<Token> tokens = Tokenize(code);
  std::map<size_t, std::string> after;  // text to add after a token (closing a rewritten call)
  std::set<size_t> dropped;             // tokens left out
  // The shader's functions (a name after a type at depth 0, before '('): 1.10 and 1.20 give
  // functions a name space of their own (4.2), 4.50 does not, so each becomes arb_f_<name>
  // where it is called or declared.
  std::set<std::string_view> functions;
  for (size_t i = 1, level = 0; i + 1 < tokens.size(); ++i) {
    if (tokens[i].text == "{") ++level;
    if (tokens[i].text == "}" && level > 0) --level;
    if (level == 0 && tokens[i].kind == Token::Identifier && tokens[i + 1].text == "(" &&
        tokens[i - 1].kind == Token::Identifier && tokens[i].text != "main" &&
        !lower::IsBuiltinFunction(tokens[i].text)) {
      functions.insert(tokens[i].text);
    }
  }
  // Globals initialized in their declaration ("vec4 p = gl_Vertex;", which 1.10 allows from
  // any expression): SPIR-V runs such initializers before main, before the generated main has
  // fed the inputs they may read. Each becomes "vec4 p; vec4 arb_init_p() { return
  // gl_Vertex; }", and main's body starts with "p = arb_init_p();", in declaration order.
  {
    static const std::set<std::string_view> kNotTypes = {
        "uniform", "varying", "attribute", "const", "invariant", "centroid", "return", "else"};
    std::string inits;
    size_t main_body = std::string::npos;
    for (size_t i = 0, level = 0; i + 2 < tokens.size(); ++i) {
      if (tokens[i].text == "{") ++level;
      if (tokens[i].text == "}" && level > 0) --level;
      if (level == 0 && tokens[i].text == "main" && tokens[i + 1].text == "(") {
        size_t k = i + 1;
        while (k < tokens.size() && tokens[k].text != ")") ++k;
        if (k + 1 < tokens.size() && tokens[k + 1].text == "{") main_body = k + 1;
      }
      const bool start = i == 0 || tokens[i - 1].text == ";" || tokens[i - 1].text == "}";
      if (level != 0 || !start || tokens[i].kind != Token::Identifier ||
          kNotTypes.count(tokens[i].text) > 0 || tokens[i + 1].kind != Token::Identifier ||
          tokens[i + 2].text != "=") {
        continue;
      }
      const size_t end = StatementEnd(tokens, i);
      int nesting = 0;
      bool single = true;  // one declarator: "vec4 a = x, b = y;" is left alone
      for (size_t k = i + 3; k < end; ++k) {
        if (tokens[k].text == "(" || tokens[k].text == "[") ++nesting;
        if (tokens[k].text == ")" || tokens[k].text == "]") --nesting;
        if (nesting == 0 && tokens[k].text == ",") single = false;
      }
      // A name the loop below spells its own way (a 1.20 keyword in 1.10, a built-in
      // function's name) keeps its initializer where it is.
      const std::string_view declared = tokens[i + 1].text;
      if (!single || end >= tokens.size() || lower::IsBuiltinFunction(declared) ||
          (l->version < 120 && lower::IsKeywordFrom120(declared))) {
        continue;
      }
      const std::string name = LoweredIdentifier(tokens[i + 1].text);
      const std::string type = LoweredIdentifier(tokens[i].text);
      dropped.insert(i + 2);
      after[i + 1] += fmt::format("; {} arb_init_{}() {{ return", type, name);
      after[end] += " }";
      inits += fmt::format(" {0} = arb_init_{0}();", name);
    }
    if (main_body != std::string::npos && !inits.empty()) after[main_body] += inits;
  }
  std::set<std::string> declared_unsized;
  int depth = 0;
  int struct_depth = -1;  // the depth outside the structure being defined; -1: none
  size_t outer_start = std::string::npos;  // where its definition starts in `out`
  struct Inner {
    size_t start = std::string::npos;  // a structure defined inside it: its start in `out`
    int depth = -1;                    // the depth outside its body
    std::string name;
  } inner;
  int nameless = 0;
  size_t copied = 0;  // `code` is copied up to here
  std::string& out = l->out;
  for (size_t i = 0; i < tokens.size(); ++i) {
    const Token& t = tokens[i];
    auto next = [&](size_t k) { return i + k < tokens.size() ? tokens[i + k].text : ""; };
    // The text between the tokens as written (blanks, newlines, multi-character operators
    // split into tokens are rebuilt by copying).
    out.append(code.substr(copied, t.offset - copied));
    copied = t.offset + t.text.size();
    if (dropped.count(i) > 0) continue;
    if (t.text == "{") ++depth;
    if (t.text == "}") --depth;
    std::string spelled(t.text);
    if (t.text == "{" && i > 0 &&
        (tokens[i - 1].text == "struct" || (i > 1 && tokens[i - 2].text == "struct"))) {
      if (struct_depth < 0) {
        struct_depth = depth - 1;
      } else if (inner.depth < 0 && inner.start != std::string::npos) {
        inner.depth = depth - 1;
        if (tokens[i - 1].text == "struct") spelled = inner.name + " {";  // a nameless one
      } else {
        return Refuse(l, "a structure defined inside a structure inside a structure");
      }
    }
    if (t.text == "}" && depth == struct_depth) {
      struct_depth = -1;
      outer_start = std::string::npos;
    }
    if (t.text == "struct") {
      if (struct_depth < 0) {
        outer_start = out.size();
      } else {
        // 4.50 nests no structure definition (1.10 does): the inner one is moved before the
        // outer and named where it stood.
        inner.start = out.size();
        inner.name = tokens.size() > i + 2 && tokens[i + 1].kind == Token::Identifier &&
                             tokens[i + 2].text == "{"
                         ? LoweredIdentifier(tokens[i + 1].text)
                         : fmt::format("arb_s_{}", nameless++);
      }
    }
    if (t.kind == Token::Identifier && t.text != "struct") {
      const std::string_view w = t.text;
      const bool call = next(1) == "(";
      // GLSL 1.10 leaves 1.20's new keywords to the shader's names.
      if (l->version < 120 && lower::IsKeywordFrom120(w)) {
        out += fmt::format("arb_u_{}", w);
        continue;
      }
      // A variable named like a built-in function hides it in 1.10 and 1.20 (not in 4.50);
      // a function that redefines one replaces every overload of the name (refused).
      if (lower::IsBuiltinFunction(w) && !w.starts_with("gl_")) {
        const std::string_view before = i > 0 ? tokens[i - 1].text : "";
        if (call && i > 0 && tokens[i - 1].kind == Token::Identifier && before != "return" &&
            before != "else" && before != "do") {
          return Refuse(l, fmt::format("a redefinition of the built-in function {}", w));
        }
        if (!call) {
          out += fmt::format("arb_u_{}", w);
          continue;
        }
      }
      if (depth == 0 && w == "uniform") {
        const size_t end = StatementEnd(tokens, i);
        for (size_t k = i + 1; k + 1 < end; ++k) {
          if (tokens[k].text != "[" || tokens[k + 1].text != "]") continue;
          // 4.50 sizes no uniform implicitly: the size glslang found, declared once.
          const std::string name(tokens[k - 1].text);
          auto size = l->implicit_sizes.find(name);
          if (size == l->implicit_sizes.end() || size->second <= 0 ||
              declared_unsized.count(name) > 0) {
            return Refuse(l, "a uniform array declared without a size");
          }
          declared_unsized.insert(name);
          after[k] += std::to_string(size->second);
        }
      }
      if (depth == 0 && w == "uniform") {
        const size_t end = StatementEnd(tokens, i);
        for (size_t k = i; k < end; ++k) {
          if (tokens[k].text == "=") return Refuse(l, "a uniform initializer (GLSL 1.20 4.3.5)");
        }
      }
      if (depth == 0 && (w == "varying" || w == "invariant" || w == "attribute")) {
        const size_t end = StatementEnd(tokens, i);
        bool builtin = false;
        bool declares = false;
        for (size_t k = i + 1; k < end; ++k) {
          if (tokens[k].text.starts_with("gl_")) builtin = true;
          if (tokens[k].kind == Token::Identifier && tokens[k].text != "varying" &&
              tokens[k].text != "centroid" && !tokens[k].text.starts_with("gl_")) {
            declares = true;
          }
        }
        // A redeclaration of a built-in (gl_TexCoord's size, "invariant gl_Position;"): the
        // lowering declares them itself.
        if (builtin && (w == "varying" || !declares)) {
          for (size_t k = i; k <= end && k < tokens.size(); ++k) dropped.insert(k);
          continue;
        }
        if (w == "invariant") continue;  // invariance is what one point per vector gives
      }
      if (w == "attribute" || w == "varying") continue;  // plain globals the main feeds
      if (w == "centroid" && next(1) == "varying") continue;
      if (w == "main") {
        spelled = "arb_main";
      } else if (call && functions.count(w) > 0) {
        spelled = fmt::format("arb_f_{}", w);
      } else if (w == "dFdy" && call) {
        // GL's window y grows upwards, Vulkan's framebuffer y downwards (the viewport of
        // negative height flips the geometry, not the derivatives).
        spelled = "(-dFdy";
        after[Closing(tokens, i + 1)] += ")";
      } else if (w == "ftransform" && next(1) == "(" && next(2) == ")") {
        l->state.insert("gl_ModelViewProjectionMatrix");
        spelled = "(arb_gl_ModelViewProjectionMatrix * arb_gl_Vertex)";
        dropped.insert(i + 1);
        dropped.insert(i + 2);
      } else if (w.starts_with("noise") && w.size() == 6 && call) {
        return Refuse(l, fmt::format("{} (Mesa's noise functions return 0)", w));
      } else if (const lower::LookupFunction* f = lower::FindLookupFunction(w);
                 f != nullptr && next(1) == "(") {
        spelled = std::string(f->replacement);
        if (f->shadow) {
          // shadow2D(s, c) -> arb_shadow(texture(s, c), arb_depthmode_s)
          const size_t close = Closing(tokens, i + 1);
          if (close >= tokens.size() || i + 3 >= close || tokens[i + 2].kind != Token::Identifier ||
              tokens[i + 3].text != ",") {
            return Refuse(l, fmt::format("{} of a sampler that is not a uniform's name", w));
          }
          const std::string sampler(tokens[i + 2].text);
          l->shadow.insert(sampler);
          l->shadow_helper = true;
          spelled.insert(0, "arb_shadow(");
          after[close] += fmt::format(", arb_depthmode_{})", LoweredIdentifier(sampler));
        }
      } else if (w.starts_with("gl_")) {
        if (!LowerBuiltin(l, w, &spelled)) return false;
      } else if (w == "sampler2DRect" || w == "sampler2DRectShadow" ||
                 w.starts_with("texture2DRect") || w.starts_with("shadow2DRect")) {
        return Refuse(l, fmt::format("{} (rectangle textures)", w));
      } else {
        spelled = LoweredIdentifier(w);
      }
    }
    out += spelled;
    if (auto it = after.find(i); it != after.end()) out += it->second;
    if (t.text == "}" && depth == inner.depth && inner.start != std::string::npos &&
        outer_start != std::string::npos) {
      const std::string definition = out.substr(inner.start) + ";\n";
      out.erase(inner.start);
      out += inner.name;
      out.insert(outer_start, definition);
      outer_start += definition.size();
      inner = {};
    }
  }
  out.append(code.substr(copied));
  return true;
}

}  // namespace

std::string LoweredIdentifier(std::string_view name) {
  if (name.starts_with("gl_")) return fmt::format("arb_{}", name);
  if (name.starts_with("arb_") || lower::IsReservedIn450(name)) {
    return fmt::format("arb_u_{}", name);
  }
  return std::string(name);
}

LoweredShader LowerForVulkan(Stage stage, std::string_view text) {
  LoweredShader result;
  std::string preprocessed;
  int version = 110;
  std::map<std::string, int> implicit_sizes;
  if (!Preprocess(stage, text, &preprocessed, &version, &implicit_sizes, &result.not_applicable)) {
    return result;
  }
  // The directives glslang leaves (#version, #extension, #pragma, #line) are blanked: an
  // extension the shader enables is one the lowering does not know.
  // The shader's own #extension lines (those of Mesa's implicit extensions in glslang's
  // preamble enable nothing that the tokens below do not refuse).
  const std::string source = BlankComments(text);
  for (const Directive& d : Directives(source)) {
    if (d.name == "extension" && d.words.size() >= 3 && d.words[2].text != "disable" &&
        !ChangesNothing(d.words[0].text)) {
      result.not_applicable = Refusal(fmt::format("#extension {}", d.words[0].text));
      return result;
    }
  }
  // The words glslang reserves that the shader's version leaves free were renamed for glslang
  // 12 (source_text.h): their own spelling, renamed below where 4.50 reserves them.
  std::string code = BlankComments(RestoreSpelling(preprocessed));
  Lowering l{stage, version, std::move(implicit_sizes), {}, {}, {}, {}, {}, false};
  for (const Directive& d : Directives(code)) {
    std::fill(code.begin() + d.hash, code.begin() + d.end, ' ');
  }
  if (!Rewrite(code, &l)) {
    result.not_applicable = l.refusal;
    return result;
  }
  result.text = Declarations(l);
  for (const std::string& s : l.shadow) {
    result.shadow_samplers.push_back(s);
    result.text += fmt::format("uniform vec4 arb_depthmode_{};\n", LoweredIdentifier(s));
  }
  result.text += Globals(stage);
  if (l.shadow_helper) result.text += kShadowHelper;
  result.text += l.out;
  result.state.assign(l.state.begin(), l.state.end());
  // A constant index past a vector, matrix or array is undefined in 1.10 and 1.20 (5.5, 5.6)
  // and an error in 4.50.
  CompiledPair compiled;
  std::string error;
  const std::string whole = result.text + "void main() { arb_main(); }\n";
  if (!CompileLoweredPair(stage == Stage::Vertex ? whole : "",
                          stage == Stage::Fragment ? whole : "", &compiled, &error) &&
      error.find("index out of range") != std::string::npos) {
    result = LoweredShader{};
    result.not_applicable = Refusal("a constant index out of range (undefined in GLSL 1.10)");
  }
  return result;
}

}  // namespace arbiter::glsl
