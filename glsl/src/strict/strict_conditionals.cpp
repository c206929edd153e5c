// GLSL 1.10 3.3: "Expressions following #if and #elif are restricted to expressions operating
// on literal integer constants, plus identifiers consumed by the defined operator." glslang
// (as a C preprocessor) takes any other identifier left after macro expansion as 0, silently.
// This rule follows the conditional directives as a preprocessor does, expanding object-like
// macros, and reports such an identifier in every #if or #elif that is evaluated. Where it
// cannot tell a value (a function-like macro), it reports nothing inside that group.
#include <fmt/format.h>

#include <cctype>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "strict.h"

namespace arbiter::glsl {
namespace {

struct Tok {
  std::string text;
  size_t offset;  // in the file, of the token or of the macro name it was expanded from
};

// The tokens of a directive's operand text: identifiers, numbers, two-character operators
// and single characters.
std::vector<Tok> Lex(std::string_view text, size_t base) {
  static const std::set<std::string_view> kPairs = {"<<", ">>", "<=", ">=", "==", "!=", "&&", "||"};
  std::vector<Tok> out;
  for (size_t i = 0; i < text.size();) {
    if (std::isspace(static_cast<unsigned char>(text[i]))) {
      ++i;
      continue;
    }
    size_t start = i;
    if (IsIdentChar(text[i])) {
      while (i < text.size() && IsIdentChar(text[i])) ++i;
    } else if (i + 1 < text.size() && kPairs.count(text.substr(i, 2))) {
      i += 2;
    } else {
      ++i;
    }
    out.push_back({std::string(text.substr(start, i - start)), base + start});
  }
  return out;
}

struct Macro {
  bool function_like = false;
  std::string body;
};

// Evaluates one #if or #elif expression; nullopt when it cannot (a function-like macro, a
// malformed expression: glslang reports the latter).
class Condition {
 public:
  Condition(const std::map<std::string, Macro, std::less<>>& macros, std::vector<Tok>* undefined)
      : macros_(macros), undefined_(undefined) {}

  std::optional<long long> Evaluate(const std::vector<Tok>& tokens) {
    if (!Expand(tokens, 0)) return std::nullopt;
    pos_ = 0;
    std::optional<long long> value = Binary(0);
    if (!value || pos_ != expanded_.size()) return std::nullopt;
    return value;
  }

 private:
  // Replaces 'defined X', 'defined ( X )' and macros; an identifier left is reported and 0.
  bool Expand(const std::vector<Tok>& tokens, int depth) {
    if (depth > 32) return false;
    for (size_t i = 0; i < tokens.size(); ++i) {
      const Tok& t = tokens[i];
      if (!IsIdentStart(t.text[0])) {
        expanded_.push_back(t);
        continue;
      }
      if (t.text == "defined") {
        size_t name = i + 1;
        bool paren = name < tokens.size() && tokens[name].text == "(";
        if (paren) ++name;
        if (name >= tokens.size() || !IsIdentStart(tokens[name].text[0])) return false;
        if (paren && (name + 1 >= tokens.size() || tokens[name + 1].text != ")")) return false;
        bool is_defined = macros_.count(tokens[name].text) > 0 || Predefined(tokens[name].text);
        expanded_.push_back({is_defined ? "1" : "0", t.offset});
        i = paren ? name + 1 : name;
        continue;
      }
      auto macro = macros_.find(t.text);
      if (macro != macros_.end()) {
        if (macro->second.function_like) return false;
        std::vector<Tok> body = Lex(macro->second.body, 0);
        for (Tok& b : body) b.offset = t.offset;  // reported at the name in the directive
        if (!Expand(body, depth + 1)) return false;
        continue;
      }
      if (Predefined(t.text)) {
        expanded_.push_back({"1", t.offset});
        continue;
      }
      // Extension macros ("GL_" names, reserved to the implementation) may be defined by it.
      if (t.text.compare(0, 3, "GL_") == 0) return false;
      undefined_->push_back(t);
      expanded_.push_back({"0", t.offset});
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
      std::string op = expanded_[pos_].text;
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
    std::string t = expanded_[pos_++].text;
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
      long long v = std::stoll(t, &used, 0);  // decimal, octal (0...) and hexadecimal (0x...)
      return used == t.size() ? std::optional<long long>(v) : std::nullopt;
    } catch (...) {
      return std::nullopt;
    }
  }

  const std::map<std::string, Macro, std::less<>>& macros_;
  std::vector<Tok>* undefined_;
  std::vector<Tok> expanded_;
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
std::map<std::string, Macro, std::less<>> PreambleMacros(std::string_view preamble) {
  std::map<std::string, Macro, std::less<>> macros;
  const std::string blanked = BlankComments(preamble);
  for (const Directive& d : Directives(blanked)) {
    if (d.words.empty() || d.words[0].kind != Token::Identifier) continue;
    std::string name(d.words[0].text);
    if (d.name == "undef") {
      macros.erase(name);
    } else if (d.name == "define") {
      size_t name_end = d.words[0].offset + d.words[0].text.size();
      Macro macro;
      macro.function_like = name_end < d.end && blanked[name_end] == '(';
      macro.body = blanked.substr(name_end, d.end - name_end);
      macros[name] = macro;
    }
  }
  return macros;
}

}  // namespace

void CheckConditionals(const StrictContext& ctx) {
  for (size_t index = 0; index < ctx.sources.size(); ++index) {
    const compiler::SourceFile* file = ctx.sources[index];
    const std::string& blanked = BlankedText(ctx, index);
    std::map<std::string, Macro, std::less<>> macros = PreambleMacros(ctx.preamble);
    std::vector<Group> groups;
    auto active = [&] { return groups.empty() || groups.back().active; };
    auto judged = [&] { return groups.empty() || !groups.back().unknown; };
    // Evaluates a condition, reporting its undefined identifiers; nullopt when unknown.
    auto evaluate = [&](const std::vector<Tok>& tokens) -> std::optional<bool> {
      std::vector<Tok> undefined;
      std::optional<long long> value = Condition(macros, &undefined).Evaluate(tokens);
      if (!value && undefined.empty()) return std::nullopt;
      for (const Tok& t : undefined) {
        ctx.sink->Report(Info(Diag::IfUndefinedIdentifier), file,
                         {static_cast<uint32_t>(t.offset),
                          static_cast<uint32_t>(t.offset + std::min(t.text.size(), size_t{64}))},
                         fmt::format("'{}' is not a macro: #if and #elif expressions operate on "
                                     "integer literals and 'defined' only (GLSL 1.10 section "
                                     "3.3); glslang takes an undefined name as 0",
                                     t.text));
      }
      return value.value_or(0) != 0;
    };
    for (uint32_t n = 1; n <= file->line_count(); ++n) {
      std::string_view line =
          std::string_view(blanked).substr(file->LineStart(n), file->LineText(n).size());
      size_t first = line.find_first_not_of(" \t");
      if (first == std::string_view::npos || line[first] != '#') continue;
      size_t word = line.find_first_not_of(" \t", first + 1);
      if (word == std::string_view::npos) continue;
      size_t word_end = word;
      while (word_end < line.size() && IsIdentChar(line[word_end])) ++word_end;
      std::string_view directive = line.substr(word, word_end - word);
      std::string_view rest = line.substr(word_end);
      size_t base = file->LineStart(n) + word_end;
      bool in_unknown = false;
      for (const Group& g : groups) in_unknown |= g.unknown;
      if (directive == "define" && !active() && in_unknown) {
        // Perhaps defined: its uses make a condition unknown, as a function-like macro does.
        std::vector<Tok> tokens = Lex(rest, base);
        if (!tokens.empty()) macros[tokens[0].text] = Macro{true, ""};
      } else if (directive == "define" && active()) {
        std::vector<Tok> tokens = Lex(rest, base);
        if (tokens.empty() || !IsIdentStart(tokens[0].text[0])) continue;
        size_t name_end = tokens[0].offset - base + tokens[0].text.size();
        Macro macro;
        macro.function_like = name_end < rest.size() && rest[name_end] == '(';
        macro.body = std::string(rest.substr(name_end));
        macros[tokens[0].text] = macro;
      } else if (directive == "undef" && active()) {
        std::vector<Tok> tokens = Lex(rest, base);
        if (!tokens.empty()) macros.erase(tokens[0].text);
      } else if (directive == "ifdef" || directive == "ifndef") {
        std::vector<Tok> tokens = Lex(rest, base);
        bool defined = !tokens.empty() && macros.count(tokens[0].text) > 0;
        bool value = directive == "ifdef" ? defined : !defined;
        bool parent = active();
        groups.push_back({parent, parent && value, value, !judged()});
      } else if (directive == "if") {
        bool parent = active();
        std::optional<bool> value;
        if (parent && judged()) value = evaluate(Lex(rest, base));
        bool unknown = !judged() || (parent && !value);
        groups.push_back({parent, parent && value.value_or(false), value.value_or(true), unknown});
      } else if (directive == "elif" && !groups.empty()) {
        Group& g = groups.back();
        if (g.parent_active && !g.taken && !g.unknown) {
          std::optional<bool> value = evaluate(Lex(rest, base));
          g.unknown = !value;
          g.active = value.value_or(false);
          g.taken = value.value_or(true);
        } else {
          g.active = false;
        }
      } else if (directive == "else" && !groups.empty()) {
        Group& g = groups.back();
        g.active = g.parent_active && !g.taken && !g.unknown;
        g.taken = true;
      } else if (directive == "endif" && !groups.empty()) {
        groups.pop_back();
      }
    }
  }
}

}  // namespace arbiter::glsl
