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

#include "strict.h"

namespace arbiter::glsl {
namespace {

bool IsDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

struct Tok {
  std::string text;
  const compiler::SourceFile* file = nullptr;
  uint32_t offset = 0;  // in the file: of the token, or of the macro name it came from
  uint32_t length = 0;  // of the reported range
  std::string macro;    // the object-like macro it was expanded from, if any
  bool opaque = false;  // a function-like or implementation macro: value unknown
  bool unsure = false;  // in a conditional group whose value is not known
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

// The tokens of one line of code (comments already blanked): identifiers, numbers and single
// punctuation characters.
void Lex(std::string_view line, uint32_t base, const compiler::SourceFile* file,
         std::vector<Tok>* out) {
  for (size_t i = 0; i < line.size();) {
    char c = line[i];
    if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
      continue;
    }
    size_t start = i;
    if (IsIdentStart(c)) {
      while (i < line.size() && IsIdentChar(line[i])) ++i;
    } else if (IsDigit(c) || (c == '.' && i + 1 < line.size() && IsDigit(line[i + 1]))) {
      // Digits, letters (exponent, suffix, hexadecimal), '.', and the sign of an exponent.
      while (i < line.size()) {
        char d = line[i];
        bool sign = (d == '+' || d == '-') && (line[i - 1] == 'e' || line[i - 1] == 'E') &&
                    !(line.substr(start, 2) == "0x" || line.substr(start, 2) == "0X");
        if (!IsIdentChar(d) && d != '.' && !sign) break;
        ++i;
      }
    } else {
      ++i;
    }
    Tok tok;
    tok.text = std::string(line.substr(start, i - start));
    tok.file = file;
    tok.offset = base + static_cast<uint32_t>(start);
    tok.length = static_cast<uint32_t>(i - start);
    out->push_back(std::move(tok));
  }
}

struct Macro {
  bool function_like = false;
  bool unsure = false;  // defined or undefined in a group whose value is not known
  std::vector<Tok> body;
};

// The tokens glslang parses, as far as this rule can tell: directives followed, groups whose
// value is known to be false skipped, object-like macros expanded. The source strings are
// one shader, read in order (a macro or a group goes on into the next string).
class Preprocessed {
 public:
  explicit Preprocessed(const StrictContext& ctx) {
    for (size_t i = 0; i < ctx.sources.size(); ++i) Read(*ctx.sources[i], BlankedText(ctx, i));
  }

  const std::vector<Tok>& tokens() const { return tokens_; }

 private:
  void Read(const compiler::SourceFile& file, const std::string& text) {
    for (uint32_t n = 1; n <= file.line_count(); ++n) {
      uint32_t start = file.LineStart(n);
      std::string_view line = std::string_view(text).substr(start, file.LineText(n).size());
      size_t first = line.find_first_not_of(" \t\r\f\v");
      if (first == std::string_view::npos) continue;
      if (line[first] == '#') {
        Directive(line.substr(first + 1), start + static_cast<uint32_t>(first + 1), &file);
        continue;
      }
      if (Skipped()) continue;
      std::vector<Tok> raw;
      Lex(line, start, &file, &raw);
      bool unsure = Unsure();
      for (Tok& t : raw) {
        t.unsure = unsure;
        Expand(t, 0);
      }
    }
  }

  enum class State { kActive, kInactive, kUnsure };
  struct Group {
    bool parent_skipped;
    State state;
    bool taken;  // a branch was taken
    bool maybe;  // a branch may have been taken (a value not known)
  };
  enum class Value { kFalse, kTrue, kUnknown };

  bool Skipped() const {
    for (const Group& g : groups_) {
      if (g.state == State::kInactive) return true;
    }
    return false;
  }
  bool Unsure() const {
    for (const Group& g : groups_) {
      if (g.state == State::kUnsure) return true;
    }
    return false;
  }

  Value Defined(const std::string& name) const {
    auto it = macros_.find(name);
    if (it != macros_.end()) return it->second.unsure ? Value::kUnknown : Value::kTrue;
    if (name == "__LINE__" || name == "__FILE__" || name == "__VERSION__") return Value::kTrue;
    if (name.compare(0, 3, "GL_") == 0) return Value::kUnknown;  // the implementation's
    return Value::kFalse;
  }

  // #if and #elif: an integer literal, or `defined X` or `defined ( X )`, each perhaps negated
  // with '!'; any other expression has a value this rule does not know.
  Value Evaluate(const std::vector<Tok>& operands) const {
    size_t k = 0;
    bool negate = false;
    for (; k < operands.size() && operands[k].text == "!"; ++k) negate = !negate;
    std::vector<std::string> rest;
    for (; k < operands.size(); ++k) rest.push_back(operands[k].text);
    Value v = Value::kUnknown;
    if (rest.size() == 1 && IsDigit(rest[0][0]) && !IsFloatLiteral(rest[0])) {
      try {
        size_t used = 0;
        long long n = std::stoll(rest[0], &used, 0);  // decimal, octal, hexadecimal
        if (used == rest[0].size()) v = n != 0 ? Value::kTrue : Value::kFalse;
      } catch (...) {
        v = Value::kUnknown;
      }
    } else if (rest.size() == 2 && rest[0] == "defined" && IsIdentStart(rest[1][0])) {
      v = Defined(rest[1]);
    } else if (rest.size() == 4 && rest[0] == "defined" && rest[1] == "(" &&
               IsIdentStart(rest[2][0]) && rest[3] == ")") {
      v = Defined(rest[2]);
    }
    if (negate && v != Value::kUnknown) v = v == Value::kTrue ? Value::kFalse : Value::kTrue;
    return v;
  }

  static State StateOf(Value v) {
    return v == Value::kTrue    ? State::kActive
           : v == Value::kFalse ? State::kInactive
                                : State::kUnsure;
  }

  void Directive(std::string_view rest, uint32_t base, const compiler::SourceFile* file) {
    std::vector<Tok> words;
    Lex(rest, base, file, &words);
    if (words.empty()) return;
    std::string directive = words[0].text;
    std::vector<Tok> operands(words.begin() + 1, words.end());
    bool skipped = Skipped();
    if (directive == "ifdef" || directive == "ifndef") {
      Value v = Value::kUnknown;
      if (!operands.empty()) v = Defined(operands[0].text);
      if (directive == "ifndef" && v != Value::kUnknown) {
        v = v == Value::kTrue ? Value::kFalse : Value::kTrue;
      }
      Push(skipped, v);
    } else if (directive == "if") {
      Push(skipped, Evaluate(operands));
    } else if ((directive == "elif" || directive == "else") && !groups_.empty()) {
      Group& g = groups_.back();
      if (g.parent_skipped || g.taken) {
        g.state = State::kInactive;
        return;
      }
      Value v = directive == "else" ? Value::kTrue : Evaluate(operands);
      if (g.maybe && v != Value::kFalse) v = Value::kUnknown;
      g.state = StateOf(v);
      g.taken = v == Value::kTrue;
      g.maybe = g.maybe || v == Value::kUnknown;
    } else if (directive == "endif" && !groups_.empty()) {
      groups_.pop_back();
    } else if (directive == "define" && !skipped && !operands.empty() && IsIdent(operands[0])) {
      const Tok& name = operands[0];
      Macro macro;
      macro.unsure = Unsure();
      size_t name_end = name.offset - base + name.text.size();
      macro.function_like = name_end < rest.size() && rest[name_end] == '(';
      macro.body.assign(operands.begin() + 1, operands.end());
      macros_[name.text] = std::move(macro);
    } else if (directive == "undef" && !skipped && !operands.empty()) {
      if (Unsure()) {
        macros_[operands[0].text] = Macro{true, true, {}};
      } else {
        macros_.erase(operands[0].text);
      }
    }
  }

  void Push(bool skipped, Value v) {
    if (skipped) {
      groups_.push_back({true, State::kInactive, true, false});
    } else {
      groups_.push_back({false, StateOf(v), v == Value::kTrue, v == Value::kUnknown});
    }
  }

  // Appends `t`, or the expansion of the macro it names (at the macro name's location).
  void Expand(const Tok& t, int depth) {
    if (!IsIdent(t)) {
      tokens_.push_back(t);
      return;
    }
    auto it = macros_.find(t.text);
    bool implementation = it == macros_.end() && t.text.compare(0, 3, "GL_") == 0;
    if (implementation ||
        (it != macros_.end() && (it->second.function_like || it->second.unsure || depth > 32))) {
      Tok opaque = t;
      opaque.opaque = true;
      tokens_.push_back(opaque);
      return;
    }
    if (it == macros_.end() || expanding_.count(t.text)) {
      Tok plain = t;
      if (t.text == "__LINE__" || t.text == "__FILE__" || t.text == "__VERSION__") {
        // An integer, as every predefined macro is. (assign(1, c): GCC 12 -O2 warns about
        // assigning a literal here, a false -Wrestrict.)
        plain.text.assign(1, '1');
      }
      tokens_.push_back(plain);
      return;
    }
    expanding_.insert(t.text);
    for (const Tok& b : it->second.body) {
      Tok e = b;
      e.file = t.file;
      e.offset = t.offset;
      e.length = t.length;
      e.unsure = t.unsure;
      if (e.macro.empty()) e.macro = t.macro.empty() ? t.text : t.macro;
      Expand(e, depth + 1);
    }
    expanding_.erase(t.text);
  }

  std::map<std::string, Macro, std::less<>> macros_;
  std::set<std::string, std::less<>> expanding_;
  std::vector<Group> groups_;
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
      const std::string& t = toks_[i].text;
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
    const std::string& prev = toks_[k - 1].text;
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
      brace.type = toks_[k].text;
      structs_.insert(brace.type);
      ++k;
    }
    if (k < toks_.size() && toks_[k].text == "{") pending_struct_ = brace;
    return k;
  }

  // A declaration beginning with the type at `i`: variables, or a function and its parameters.
  size_t Declaration(size_t i) {
    const std::string& type = toks_[i].text;
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
      scopes_.back()[name.text] = Symbol{type, is_const, false, unsure || name.unsure};
      if (i < toks_.size() && toks_[i].text == "=") {
        for (++i; i < toks_.size(); ++i) {
          const std::string& t = toks_[i].text;
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
      const std::string& t = toks_[k].text;
      if (t == "(" || t == "[" || t == "{") ++depth;
      if (t == ")" || t == "]" || t == "}") {
        if (--depth == 0) return k;
      }
    }
    return kNone;
  }

  const Symbol* Lookup(const std::string& name) const {
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
