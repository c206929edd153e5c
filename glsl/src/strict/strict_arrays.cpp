// GLSL 1.10 4.1.9: "When an array size is specified in a declaration, it must be an integral
// constant expression (see Section 4.3.3 ...) greater than zero." 4.3.3: "An integral constant
// expression can be one of: a literal integer value; a global or local scalar integer variable
// qualified as const, not including function parameters qualified as const; an expression
// whose operands are integral constant expressions, including constructors, but excluding
// function calls." glslang 12 takes any constant int expression and folds it (int(2.0) is 2,
// int(abs(-2.0)) is 2) before arbiter sees the AST, so this rule reads the size of every
// array declaration (globals, locals, structure fields, parameters) from the tokens.
//
// 4.3.3 is read literally, operand by operand: every literal must be an integer, every
// variable a const scalar int (the rule keeps a table of the declarations it reads, by scope),
// and no function may be called; constructors and operators, '?:' among them, are
// transparent. So `int(2.0)`, `int(f)` with a const float f, `v.y` with a const ivec2 v and
// `true ? 2 : 3` are not integral, while `int(3)`, `ivec2(2, 3).y` and `1 > 0 ? 2 : 3` are.
// What glslang rejects itself (uniforms, non-const variables, parameters, user function calls
// outside a folded constant) never reaches this rule: it runs only on a shader glslang accepts.
//
// Macros: object-like macros are expanded as the preprocessor does, and an operand that comes
// from one is reported at the macro's name. A size that uses a function-like macro, an
// implementation macro (GL_*), or text inside a conditional group whose value this rule cannot
// tell is not judged: it reports nothing rather than a false error.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "../conditionals.h"
#include "strict.h"

namespace arbiter::glsl {
namespace {

bool IsDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

// A token as glslang parses it, as far as this rule can tell (Preprocessed).
struct Tok {
  std::string_view text;  // views a source, the preamble or a literal
  const compiler::SourceFile* file = nullptr;
  uint32_t offset = 0;     // in the file: of the token, or of the macro name it came from
  uint32_t length = 0;     // of the reported range
  std::string_view macro;  // the object-like macro it was expanded from, if any
  bool opaque = false;     // a function-like or implementation macro: value unknown
  bool unsure = false;     // in a conditional group whose value is not known
};

bool IsIdent(const Tok& t) { return IsIdentStart(t.text[0]); }
bool IsNumber(const Tok& t) {
  return IsDigit(t.text[0]) || (t.text[0] == '.' && t.text.size() > 1);
}

// A float literal of 4.1.4 (a '.' or an exponent), or one with a suffix, which glslang takes.
bool IsFloatLiteral(std::string_view text) {
  if (text.size() > 1 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X')) return false;
  return text.find_first_of(".eEfF") != std::string_view::npos;
}

// The tokens glslang parses, as far as this rule can tell: directives followed
// (conditionals.h), groups known to be false skipped, object-like macros expanded. The
// source strings are one shader, read in order (a macro or a group goes on into the next
// string).
class Preprocessed {
 public:
  explicit Preprocessed(const StrictContext& ctx) : tracker_(ctx.preamble) {
    for (size_t i = 0; i < ctx.sources.size(); ++i) Read(ctx, i);
  }

  const std::vector<Tok>& tokens() const { return tokens_; }

 private:
  // The code tokens of one source and its directives, in text order.
  void Read(const StrictContext& ctx, size_t index) {
    const std::vector<Token>& code = SourceTokens(ctx, index);
    auto next = code.begin();
    auto code_before = [&](uint32_t end) {
      for (; next != code.end() && next->offset < end; ++next) Code(*next, ctx.sources[index]);
    };
    for (const Directive& d : Directives(BlankedText(ctx, index))) {
      code_before(d.hash);
      tracker_.Follow(d);
    }
    code_before(UINT32_MAX);
  }

  void Code(const Token& t, const compiler::SourceFile* file) {
    if (tracker_.reach() == Reach::Skipped) return;
    Tok tok;
    tok.text = t.text;
    tok.file = file;
    tok.offset = t.offset;
    tok.length = static_cast<uint32_t>(t.text.size());
    tok.unsure = tracker_.reach() == Reach::Unknown;
    Expand(tok, 0);
  }

  // Appends `t`, or the expansion of the macro it names (at the macro name's location).
  void Expand(const Tok& t, int depth) {
    if (!IsIdent(t)) {
      tokens_.push_back(t);
      return;
    }
    const MacroTable& macros = tracker_.macros();
    auto it = macros.find(t.text);
    // A GL_ name the implementation may define. (A name an #include may define is read as
    // it stands: if it is no macro, it is no const int declared here either.)
    bool implementation = it == macros.end() && t.text.substr(0, 3) == "GL_";
    if (implementation ||
        (it != macros.end() && (it->second.function_like || it->second.unsure || depth > 32))) {
      Tok opaque = t;
      opaque.opaque = true;
      tokens_.push_back(opaque);
      return;
    }
    if (it == macros.end() || expanding_.count(t.text)) {
      Tok plain = t;
      // An integer, as every predefined macro is.
      if (t.text == "__LINE__" || t.text == "__FILE__" || t.text == "__VERSION__") plain.text = "1";
      tokens_.push_back(plain);
      return;
    }
    expanding_.emplace(t.text);
    for (const Token& b : it->second.body) {
      Tok e = t;
      e.text = b.text;
      if (e.macro.empty()) e.macro = t.text;  // the outermost macro: views the source
      Expand(e, depth + 1);
    }
    expanding_.erase(std::string(t.text));
  }

  GroupTracker tracker_;
  std::set<std::string, std::less<>> expanding_;
  std::vector<Tok> tokens_;
};

bool IsBasicType(std::string_view t) {
  static const std::set<std::string_view> kTypes = {
      "void",           "float",       "int",
      "bool",           "vec2",        "vec3",
      "vec4",           "ivec2",       "ivec3",
      "ivec4",          "bvec2",       "bvec3",
      "bvec4",          "mat2",        "mat3",
      "mat4",           "sampler1D",   "sampler2D",
      "sampler3D",      "samplerCube", "sampler1DShadow",
      "sampler2DShadow"};
  return kTypes.count(t) > 0;
}

bool IsConstructorType(std::string_view t) {
  return IsBasicType(t) && t != "void" && t.compare(0, 7, "sampler") != 0;
}

bool IsQualifier(std::string_view t) {
  static const std::set<std::string_view> kQualifiers = {
      "const",    "attribute", "uniform", "varying",       "in",    "out",     "inout", "invariant",
      "centroid", "flat",      "smooth",  "noperspective", "highp", "mediump", "lowp"};
  return kQualifiers.count(t) > 0;
}

struct Symbol {
  std::string type;
  bool is_const = false;
  bool parameter = false;
  bool unsure = false;
};

class ArraySizes {
 public:
  explicit ArraySizes(const StrictContext& ctx) : ctx_(ctx), pre_(ctx), toks_(pre_.tokens()) {}

  void Run() {
    scopes_.emplace_back();
    size_t i = 0;
    while (i < toks_.size()) {
      std::string_view t = toks_[i].text;
      if (t == "{") {
        scopes_.push_back(std::move(pending_));
        pending_.clear();
        braces_.push_back(std::move(pending_struct_));
        pending_struct_ = Brace{};
        ++i;
      } else if (t == "}") {
        if (scopes_.size() > 1) scopes_.pop_back();
        Brace brace;
        if (!braces_.empty()) {
          brace = braces_.back();
          braces_.pop_back();
        }
        ++i;
        if (brace.is_struct && i < toks_.size() && IsIdent(toks_[i])) {
          i = Declarators(i, brace.type, brace.is_const, brace.unsure);
        }
      } else if (t == "struct") {
        i = Struct(i);
      } else if (IsType(t) && i + 1 < toks_.size() && IsIdent(toks_[i + 1]) &&
                 !IsType(toks_[i + 1].text) && StartsDeclaration(i)) {
        i = Declaration(i);
      } else {
        ++i;
      }
    }
  }

 private:
  struct Brace {
    bool is_struct = false;
    std::string type;
    bool is_const = false;
    bool unsure = false;
  };

  bool IsType(std::string_view t) const { return IsBasicType(t) || structs_.count(t) > 0; }

  // Whether the type at `i`, after its qualifiers, begins a declaration statement.
  bool StartsDeclaration(size_t i) const {
    size_t k = i;
    while (k > 0 && IsQualifier(toks_[k - 1].text)) --k;
    if (k == 0) return true;
    std::string_view prev = toks_[k - 1].text;
    return prev == ";" || prev == "{" || prev == "}" || prev == "(";
  }

  bool HasConst(size_t i) const {
    for (size_t k = i; k > 0 && IsQualifier(toks_[k - 1].text); --k) {
      if (toks_[k - 1].text == "const") return true;
    }
    return false;
  }

  // `struct name? {`: the name becomes a type; the declarators after '}' are read there.
  size_t Struct(size_t i) {
    size_t k = i + 1;
    Brace brace;
    brace.is_struct = true;
    brace.is_const = HasConst(i);
    brace.unsure = toks_[i].unsure;
    if (k < toks_.size() && IsIdent(toks_[k])) {
      brace.type = std::string(toks_[k].text);
      structs_.insert(brace.type);
      ++k;
    }
    if (k < toks_.size() && toks_[k].text == "{") pending_struct_ = brace;
    return k;
  }

  // A declaration beginning with the type at `i`: variables, or a function and its parameters.
  size_t Declaration(size_t i) {
    const std::string type(toks_[i].text);
    if (i + 2 < toks_.size() && toks_[i + 2].text == "(") return Function(i + 2);
    return Declarators(i + 1, type, HasConst(i), toks_[i].unsure);
  }

  // The parameter list opening at `open`; its names go to the scope of the body, if any.
  size_t Function(size_t open) {
    size_t close = Match(open);
    if (close == kNone) return toks_.size();
    size_t begin = open + 1;
    for (size_t k = open + 1; k <= close; ++k) {
      if (k == close || toks_[k].text == ",") {
        Parameter(begin, k);
        begin = k + 1;
      } else if (toks_[k].text == "(" || toks_[k].text == "[") {
        size_t end = Match(k);
        if (end == kNone || end > close) return close + 1;
        k = end;
      }
    }
    if (close + 1 >= toks_.size() || toks_[close + 1].text != "{") pending_.clear();
    return close + 1;
  }

  // One parameter, tokens [begin, end): qualifiers, a type, a name, sizes.
  void Parameter(size_t begin, size_t end) {
    std::string type;
    std::string name;
    for (size_t k = begin; k < end; ++k) {
      const Tok& t = toks_[k];
      if (t.text == "[") {
        size_t close = Match(k);
        if (close == kNone || close > end) return;
        if (close > k + 1) CheckSize(k + 1, close);
        k = close;
      } else if (IsIdent(t) && !IsQualifier(t.text)) {
        (type.empty() ? type : name) = t.text;
      }
    }
    if (!name.empty()) pending_[name] = Symbol{type, false, true, toks_[begin].unsure};
  }

  // Declarators from `i` (a name): `name`, `name[size]`, `name = initializer`, separated by
  // ','. Returns the index of the first token after them.
  size_t Declarators(size_t i, const std::string& type, bool is_const, bool unsure) {
    while (i < toks_.size() && IsIdent(toks_[i])) {
      const Tok& name = toks_[i++];
      if (i < toks_.size() && toks_[i].text == "[") {
        size_t close = Match(i);
        if (close == kNone) return toks_.size();
        if (close > i + 1) CheckSize(i + 1, close);
        i = close + 1;
      }
      scopes_.back()[std::string(name.text)] = Symbol{type, is_const, false, unsure || name.unsure};
      if (i < toks_.size() && toks_[i].text == "=") {
        for (++i; i < toks_.size(); ++i) {
          std::string_view t = toks_[i].text;
          if (t == "," || t == ";" || t == "}") break;
          if (t == "(" || t == "[" || t == "{") {
            size_t end = Match(i);
            if (end == kNone) return toks_.size();
            i = end;
          }
        }
      }
      if (i < toks_.size() && toks_[i].text == ",") {
        ++i;
        continue;
      }
      break;
    }
    return i;
  }

  static constexpr size_t kNone = static_cast<size_t>(-1);

  // The index of the bracket closing the one at `open`; kNone when there is none.
  size_t Match(size_t open) const {
    int depth = 0;
    for (size_t k = open; k < toks_.size(); ++k) {
      std::string_view t = toks_[k].text;
      if (t == "(" || t == "[" || t == "{") ++depth;
      if (t == ")" || t == "]" || t == "}") {
        if (--depth == 0) return k;
      }
    }
    return kNone;
  }

  const Symbol* Lookup(std::string_view name) const {
    for (auto scope = scopes_.rbegin(); scope != scopes_.rend(); ++scope) {
      auto it = scope->find(name);
      if (it != scope->end()) return &it->second;
    }
    return nullptr;
  }

  // The size tokens [begin, end): reports the first operand that is not an integral constant
  // expression.
  void CheckSize(size_t begin, size_t end) {
    for (size_t k = begin; k < end; ++k) {
      if (toks_[k].opaque || toks_[k].unsure) return;
    }
    for (size_t k = begin; k < end; ++k) {
      const Tok& t = toks_[k];
      if (IsNumber(t)) {
        if (IsFloatLiteral(t.text))
          return Report(t, fmt::format("'{}' is a float literal", t.text));
        continue;
      }
      if (t.text == "true" || t.text == "false") {
        return Report(t, fmt::format("'{}' is a bool literal", t.text));
      }
      if (!IsIdent(t) || (k > begin && toks_[k - 1].text == ".")) continue;  // a field
      if (k + 1 < end && toks_[k + 1].text == "(") {
        if (IsConstructorType(t.text) || structs_.count(t.text)) continue;  // a constructor
        return Report(t, fmt::format("'{}' is a function call", t.text));
      }
      const Symbol* symbol = Lookup(t.text);
      // Undeclared here: a built-in constant (const int gl_MaxLights...) or a name glslang
      // resolved. Not const: glslang rejected it already.
      if (symbol == nullptr) continue;
      if (symbol->unsure || symbol->parameter || !symbol->is_const) return;
      if (symbol->type != "int") {
        return Report(t, fmt::format("'{}' is a const {}, not a scalar int", t.text, symbol->type));
      }
    }
  }

  void Report(const Tok& t, const std::string& what) {
    std::string from = t.macro.empty() ? "" : fmt::format(" (from macro '{}')", t.macro);
    ctx_.sink->Report(
        Info(Diag::ArraySizeNotIntegral), t.file, {t.offset, t.offset + t.length},
        fmt::format("array size is not an integral constant expression: {}{}; GLSL 1.10 "
                    "allows integer literals, const int variables, and operators and "
                    "constructors of these, but no function calls (sections 4.1.9, 4.3.3)",
                    what, from));
  }

  const StrictContext& ctx_;
  Preprocessed pre_;
  const std::vector<Tok>& toks_;
  std::vector<std::map<std::string, Symbol, std::less<>>> scopes_;
  std::map<std::string, Symbol, std::less<>> pending_;  // parameters, for the next '{'
  std::vector<Brace> braces_;
  Brace pending_struct_;  // the structure whose body the next '{' opens
  std::set<std::string, std::less<>> structs_;
};

}  // namespace

// 4.1.9 (both versions): an array size is an integral constant expression, "a scalar
// integer" (1.20 4.3.3); glslang takes a vector constructor, `a[ivec2(2, 2)]`, as its first
// component. A '[' whose whole operand is a vector constructor is such a size (as an index,
// glslang rejects the vector itself).
void CheckVectorSizes(const StrictContext& ctx) {
  for (const compiler::SourceFile* file : ctx.sources) {
    const std::vector<Token>& tokens = SourceTokens(ctx, file);
    for (size_t i = 0; i + 3 < tokens.size(); ++i) {
      std::string_view type = tokens[i + 1].text;
      const bool vector = type.size() == 4 || type.size() == 5
                              ? (type.substr(type.size() - 4, 3) == "vec" && type.back() >= '2' &&
                                 type.back() <= '4')
                              : false;
      if (tokens[i].text != "[" || !vector || tokens[i + 2].text != "(") continue;
      int depth = 0;
      size_t close = i + 2;
      for (; close < tokens.size(); ++close) {
        if (tokens[close].text == "(") ++depth;
        if (tokens[close].text == ")" && --depth == 0) break;
      }
      if (close + 1 >= tokens.size() || tokens[close + 1].text != "]") continue;
      const Token& t = tokens[i + 1];
      ctx.sink->Report(Info(Diag::ArraySize), file,
                       {t.offset, static_cast<uint32_t>(t.offset + t.text.size())},
                       fmt::format("an array size must be a scalar integer (an integral constant "
                                   "expression, {} sections 4.1.9 and 4.3.3), not a '{}'",
                                   VersionName(ctx), type));
    }
  }
}

// 4.1.9: "It is legal to declare an array without a size and then later re-declare the same
// name as an array of the same type and specify a size", and "illegal to declare an array
// with a size, and then later ... index the same array with an integral constant expression
// greater than or equal to the declared size": so the size given later must exceed every
// constant index used before. glslang does not compare them. Read from the tokens, with
// integer literals only: `T a[];`, `T[] a;` (1.20), uses `a[N]`, then `T a[M];`, `T[M] a;` or
// `T a[] = T[M](...)`.
void CheckRedeclaredSizes(const StrictContext& ctx) {
  auto literal = [](const Token& t) -> int {
    if (t.kind != Token::Number ||
        t.text.find_first_not_of("0123456789") != std::string_view::npos || t.text.size() > 9) {
      return -1;
    }
    return std::stoi(std::string(t.text));
  };
  for (const compiler::SourceFile* file : ctx.sources) {
    const std::vector<Token>& tk = SourceTokens(ctx, file);
    std::map<std::string_view, int> unsized;  // name -> largest constant index used (-1: none)
    auto text = [&](size_t i) { return i < tk.size() ? tk[i].text : std::string_view(); };
    for (size_t i = 0; i + 3 < tk.size(); ++i) {
      const bool ident = tk[i].kind == Token::Identifier && tk[i + 1].kind == Token::Identifier;
      // T a [ ] or T [ ] a: an unsized declaration (and T a[] = T[M](...)).
      std::string_view name;
      int size = -1;
      size_t at = i + 1;
      if (ident && text(i + 2) == "[" && text(i + 3) == "]") {
        name = tk[i + 1].text;
        if (text(i + 4) == "=" && text(i + 6) == "[" && text(i + 8) == "]" && i + 7 < tk.size()) {
          size = literal(tk[i + 7]);
        }
      } else if (tk[i].kind == Token::Identifier && text(i + 1) == "[" && text(i + 2) == "]" &&
                 i + 3 < tk.size() && tk[i + 3].kind == Token::Identifier) {
        name = tk[i + 3].text;
        at = i + 3;
      } else if (ident && text(i + 2) == "[" && text(i + 4) == "]" &&
                 unsized.count(tk[i + 1].text)) {
        name = tk[i + 1].text;  // T a [ M ]
        size = literal(tk[i + 3]);
      } else if (tk[i].kind == Token::Identifier && text(i + 1) == "[" && text(i + 3) == "]" &&
                 i + 4 < tk.size() && tk[i + 4].kind == Token::Identifier &&
                 unsized.count(tk[i + 4].text) && tk[i].text != tk[i + 4].text) {
        name = tk[i + 4].text;  // T [ M ] a
        size = literal(tk[i + 2]);
        at = i + 4;
      } else if (tk[i].kind == Token::Identifier && text(i + 1) == "[" && text(i + 3) == "]" &&
                 unsized.count(tk[i].text) && (i == 0 || tk[i - 1].kind != Token::Identifier)) {
        int index = literal(tk[i + 2]);  // a use: a [ N ]
        int& largest = unsized[tk[i].text];
        largest = std::max(largest, index);
        continue;
      }
      if (name.empty()) continue;
      auto it = unsized.find(name);
      if (it == unsized.end()) {
        if (size < 0) unsized.emplace(name, -1);
        continue;
      }
      if (size >= 0 && size <= it->second) {
        const Token& t = tk[at];
        ctx.sink->Report(
            Info(Diag::ArraySize), file,
            {t.offset, static_cast<uint32_t>(t.offset + t.text.size())},
            fmt::format("'{}' is given {} elements, but index {} was used before: an array's "
                        "size must exceed every constant index used ({} section 4.1.9)",
                        name, size, it->second, VersionName(ctx)));
      }
      if (size >= 0) unsized.erase(it);
    }
  }
}

void CheckArraySizes(const StrictContext& ctx) {
  CheckVectorSizes(ctx);
  CheckRedeclaredSizes(ctx);
  // 1.20 4.3.3: "An integral constant expression is a constant expression that evaluates to a
  // scalar integer", built-in calls included: what glslang checks.
  if (ctx.version == 110) ArraySizes(ctx).Run();
}

}  // namespace arbiter::glsl
