// GLSL 1.10 3.3: "Expressions following #if and #elif are restricted to expressions operating
// on literal integer constants, plus identifiers consumed by the defined operator." glslang
// (as a C preprocessor) takes any other identifier left after macro expansion as 0, silently.
// This rule follows the conditional directives as a preprocessor does, expanding object-like
// macros, and reports such an identifier in every #if or #elif that is evaluated. Where it
// cannot tell a value (a function-like macro), it reports nothing inside that group.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "strict.h"

namespace arbiter::glsl {
namespace {

struct Macro {
  bool function_like = false;
  std::vector<Token> body;  // operators joined; views into the blanked source or preamble
};
using Macros = std::map<std::string, Macro, std::less<>>;

// The macro a #define defines; its name is d.words[0].
Macro MacroOf(const Directive& d) {
  const Token& name = d.words[0];
  const std::span<const Token> rest = std::span(d.words).subspan(1);
  Macro macro;
  // "#define F(x)" is function-like, "#define F (x)" is not.
  macro.function_like = !rest.empty() && rest[0].text == "(" &&
                        rest[0].text.data() == name.text.data() + name.text.size();
  macro.body = JoinOperators(rest);
  return macro;
}

// Evaluates one #if or #elif expression; nullopt when it cannot (a function-like macro, a
// malformed expression: glslang reports the latter).
class Condition {
 public:
  Condition(const Macros& macros, std::vector<Token>* undefined)
      : macros_(macros), undefined_(undefined) {}

  std::optional<long long> Evaluate(std::span<const Token> tokens) {
    if (!Expand(tokens, 0)) return std::nullopt;
    pos_ = 0;
    std::optional<long long> value = Binary(0);
    if (!value || pos_ != expanded_.size()) return std::nullopt;
    return value;
  }

 private:
  // Replaces 'defined X', 'defined ( X )' and macros; an identifier left is reported and 0.
  bool Expand(std::span<const Token> tokens, int depth) {
    if (depth > 32) return false;
    for (size_t i = 0; i < tokens.size(); ++i) {
      const Token& t = tokens[i];
      if (t.kind != Token::Identifier) {
        expanded_.push_back(t);
        continue;
      }
      if (t.text == "defined") {
        size_t name = i + 1;
        bool paren = name < tokens.size() && tokens[name].text == "(";
        if (paren) ++name;
        if (name >= tokens.size() || tokens[name].kind != Token::Identifier) return false;
        if (paren && (name + 1 >= tokens.size() || tokens[name + 1].text != ")")) return false;
        bool is_defined = macros_.count(tokens[name].text) > 0 || Predefined(tokens[name].text);
        expanded_.push_back({Token::Number, is_defined ? "1" : "0", t.offset});
        i = paren ? name + 1 : name;
        continue;
      }
      auto macro = macros_.find(t.text);
      if (macro != macros_.end()) {
        if (macro->second.function_like) return false;
        std::vector<Token> body = macro->second.body;
        for (Token& b : body) b.offset = t.offset;  // reported at the name in the directive
        if (!Expand(body, depth + 1)) return false;
        continue;
      }
      if (Predefined(t.text)) {
        expanded_.push_back({Token::Number, "1", t.offset});
        continue;
      }
      // Extension macros ("GL_" names, reserved to the implementation) may be defined by it.
      if (t.text.compare(0, 3, "GL_") == 0) return false;
      undefined_->push_back(t);
      expanded_.push_back({Token::Number, "0", t.offset});
    }
    return true;
  }

  static bool Predefined(std::string_view name) {
    return name == "__LINE__" || name == "__FILE__" || name == "__VERSION__";
  }

  // Precedence of a binary operator (3.3's table, 12 = '||' lowest ... 3 = '*'), 0 if none.
  static int Precedence(std::string_view op) {
    static const std::map<std::string_view, int> kTable = {
        {"||", 1}, {"&&", 2}, {"|", 3}, {"^", 4},  {"&", 5},  {"==", 6},
        {"!=", 6}, {"<", 7},  {">", 7}, {"<=", 7}, {">=", 7}, {"<<", 8},
        {">>", 8}, {"+", 9},  {"-", 9}, {"*", 10}, {"/", 10}, {"%", 10}};
    auto it = kTable.find(op);
    return it == kTable.end() ? 0 : it->second;
  }

  std::optional<long long> Binary(int min) {
    std::optional<long long> left = Unary();
    while (left && pos_ < expanded_.size()) {
      std::string_view op = expanded_[pos_].text;
      int prec = Precedence(op);
      if (prec == 0 || prec <= min) break;
      ++pos_;
      std::optional<long long> right = Binary(prec);
      if (!right) return std::nullopt;
      left = Apply(op, *left, *right);
    }
    return left;
  }

  static std::optional<long long> Apply(std::string_view op, long long a, long long b) {
    if ((op == "/" || op == "%") && b == 0) return std::nullopt;
    if (op == "||") return (a != 0 || b != 0) ? 1 : 0;
    if (op == "&&") return (a != 0 && b != 0) ? 1 : 0;
    if (op == "|") return a | b;
    if (op == "^") return a ^ b;
    if (op == "&") return a & b;
    if (op == "==") return a == b ? 1 : 0;
    if (op == "!=") return a != b ? 1 : 0;
    if (op == "<") return a < b ? 1 : 0;
    if (op == ">") return a > b ? 1 : 0;
    if (op == "<=") return a <= b ? 1 : 0;
    if (op == ">=") return a >= b ? 1 : 0;
    if (op == "<<") return b < 0 || b > 62 ? std::nullopt : std::optional<long long>(a << b);
    if (op == ">>") return b < 0 || b > 62 ? std::nullopt : std::optional<long long>(a >> b);
    if (op == "+") return a + b;
    if (op == "-") return a - b;
    if (op == "*") return a * b;
    if (op == "/") return a / b;
    return a % b;
  }

  std::optional<long long> Unary() {
    if (pos_ >= expanded_.size()) return std::nullopt;
    std::string_view t = expanded_[pos_++].text;
    if (t == "+" || t == "-" || t == "~" || t == "!") {
      std::optional<long long> v = Unary();
      if (!v) return std::nullopt;
      if (t == "-") return -*v;
      if (t == "~") return ~*v;
      if (t == "!") return *v == 0 ? 1 : 0;
      return v;
    }
    if (t == "(") {
      std::optional<long long> v = Binary(0);
      if (!v || pos_ >= expanded_.size() || expanded_[pos_].text != ")") return std::nullopt;
      ++pos_;
      return v;
    }
    if (!std::isdigit(static_cast<unsigned char>(t[0]))) return std::nullopt;
    try {
      size_t used = 0;
      long long v =
          std::stoll(std::string(t), &used, 0);  // decimal, octal (0...) and hexadecimal (0x...)
      return used == t.size() ? std::optional<long long>(v) : std::nullopt;
    } catch (...) {
      return std::nullopt;
    }
  }

  const Macros& macros_;
  std::vector<Token>* undefined_;
  std::vector<Token> expanded_;
  size_t pos_ = 0;
};

// One open #if/#ifdef/#ifndef group.
struct Group {
  bool parent_active;
  bool active;   // its current branch is compiled
  bool taken;    // a branch of the group has been taken (or its value is unknown)
  bool unknown;  // a condition could not be evaluated: nothing inside is judged
};

// The macros of the preamble (-D, -U, --preamble): defined before the shader's first line.
Macros PreambleMacros(const std::vector<Directive>& directives) {
  Macros macros;
  for (const Directive& d : directives) {
    if (d.words.empty() || d.words[0].kind != Token::Identifier) continue;
    if (d.name == "undef") {
      macros.erase(std::string(d.words[0].text));
    } else if (d.name == "define") {
      macros[std::string(d.words[0].text)] = MacroOf(d);
    }
  }
  return macros;
}

// Follows the conditional directives of one source as a preprocessor does, reporting the
// undefined identifiers of each #if and #elif it evaluates.
class Conditionals {
 public:
  Conditionals(const StrictContext& ctx, const compiler::SourceFile* file, Macros macros)
      : ctx_(ctx), file_(file), macros_(std::move(macros)) {}

  void Follow(const Directive& d) {
    if (d.name == "define" || d.name == "undef") {
      FollowMacro(d);
    } else if (d.name == "ifdef" || d.name == "ifndef" || d.name == "if") {
      Open(d);
    } else if (!groups_.empty()) {
      Continue(d);
    }
  }

 private:
  // #define and #undef count in the groups that are compiled.
  void FollowMacro(const Directive& d) {
    const std::vector<Token>& words = d.words;
    if (d.name == "define" && !Active() && InUnknown()) {
      // Perhaps defined: its uses make a condition unknown, as a function-like macro does.
      if (!words.empty()) macros_[std::string(words[0].text)] = Macro{true, {}};
    } else if (d.name == "define" && Active()) {
      if (!words.empty() && words[0].kind == Token::Identifier) {
        macros_[std::string(words[0].text)] = MacroOf(d);
      }
    } else if (d.name == "undef" && Active()) {
      if (!words.empty()) macros_.erase(std::string(words[0].text));
    }
  }

  // #if, #ifdef or #ifndef: a new group.
  void Open(const Directive& d) {
    const bool parent = Active();
    if (d.name != "if") {
      bool defined = !d.words.empty() && macros_.count(d.words[0].text) > 0;
      bool value = d.name == "ifdef" ? defined : !defined;
      groups_.push_back({parent, parent && value, value, !Judged()});
      return;
    }
    std::optional<bool> value;
    if (parent && Judged()) value = Evaluate(JoinOperators(d.words));
    bool unknown = !Judged() || (parent && !value);
    groups_.push_back({parent, parent && value.value_or(false), value.value_or(true), unknown});
  }

  // #elif, #else or #endif of the innermost group.
  void Continue(const Directive& d) {
    Group& g = groups_.back();
    if (d.name == "elif" && g.parent_active && !g.taken && !g.unknown) {
      std::optional<bool> value = Evaluate(JoinOperators(d.words));
      g.unknown = !value;
      g.active = value.value_or(false);
      g.taken = value.value_or(true);
    } else if (d.name == "elif") {
      g.active = false;
    } else if (d.name == "else") {
      g.active = g.parent_active && !g.taken && !g.unknown;
      g.taken = true;
    } else if (d.name == "endif") {
      groups_.pop_back();
    }
  }

  bool Active() const { return groups_.empty() || groups_.back().active; }
  bool Judged() const { return groups_.empty() || !groups_.back().unknown; }
  bool InUnknown() const {
    return std::ranges::any_of(groups_, [](const Group& g) { return g.unknown; });
  }

  // Evaluates a condition, reporting its undefined identifiers; nullopt when unknown.
  std::optional<bool> Evaluate(std::span<const Token> tokens) {
    std::vector<Token> undefined;
    std::optional<long long> value = Condition(macros_, &undefined).Evaluate(tokens);
    if (!value && undefined.empty()) return std::nullopt;
    for (const Token& t : undefined) {
      ctx_.sink->Report(
          Info(Diag::IfUndefinedIdentifier), file_,
          {t.offset, static_cast<uint32_t>(t.offset + std::min(t.text.size(), size_t{64}))},
          fmt::format("'{}' is not a macro: #if and #elif expressions operate on "
                      "integer literals and 'defined' only (GLSL 1.10 section "
                      "3.3); glslang takes an undefined name as 0",
                      t.text));
    }
    return value.value_or(0) != 0;
  }

  const StrictContext& ctx_;
  const compiler::SourceFile* file_;
  Macros macros_;
  std::vector<Group> groups_;
};

// The blanked text with a '\n' where the source has a lone '\r' (offsets unchanged): glslang
// ends a line there too, and so has this rule, but Directives ends lines at '\n' only.
std::string EndLinesAtCarriageReturns(std::string_view source, std::string blanked) {
  for (size_t i = 0; i < source.size(); ++i) {
    if (source[i] == '\r' && (i + 1 == source.size() || source[i + 1] != '\n')) blanked[i] = '\n';
  }
  return blanked;
}

// Whether a form feed or vertical tab comes before the directive's name on its line. This rule
// has taken such a line for text (glslang and Directives take it for a directive); kept so
// that reading the directives through Directives changes nothing.
bool FormFeedBeforeName(std::string_view text, const Directive& d) {
  const size_t line = text.rfind('\n', d.hash);
  const size_t start = line == std::string_view::npos ? 0 : line + 1;
  return !d.name.empty() &&
         text.substr(start, d.name_offset - start).find_first_of("\f\v") != std::string_view::npos;
}

}  // namespace

void CheckConditionals(const StrictContext& ctx) {
  const std::string preamble = BlankComments(ctx.preamble);  // the macros view into it
  const Macros preamble_macros = PreambleMacros(Directives(preamble));
  for (size_t index = 0; index < ctx.sources.size(); ++index) {
    const std::string text =
        EndLinesAtCarriageReturns(ctx.sources[index]->text(), BlankedText(ctx, index));
    Conditionals conditionals(ctx, ctx.sources[index], preamble_macros);
    for (const Directive& d : Directives(text)) {
      if (!FormFeedBeforeName(text, d)) conditionals.Follow(d);
    }
  }
}

}  // namespace arbiter::glsl
