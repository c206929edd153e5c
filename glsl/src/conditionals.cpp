// GLSL 1.10 3.3: "#if, #ifdef, #ifndef, #else, #elif, and #endif are defined to operate as is
// standard for C++ preprocessors", and "Expressions following #if and #elif are restricted to
// expressions operating on literal integer constants, plus identifiers consumed by the defined
// operator", with the operators and precedence of 3.3's table (conditionals.h).
#include "conditionals.h"

#include <algorithm>
#include <cctype>
#include <iterator>
#include <string>

namespace arbiter::glsl {
namespace {

// The predefined macros of 3.3. Their values are not read here: __LINE__ and __FILE__ change
// with the text, and __VERSION__ comes from the preamble (prepare.cpp defines it there).
bool Predefined(std::string_view name) {
  return name == "__LINE__" || name == "__FILE__" || name == "__VERSION__";
}

// The macro a #define defines; its name is d.words[0].
Macro MacroOf(const Directive& d) {
  const Token& name = d.words[0];
  const std::span<const Token> rest = std::span(d.words).subspan(1);
  Macro macro;
  // "#define F(x)" is function-like, "#define F (x)" is not.
  macro.function_like = !rest.empty() && rest[0].text == "(" &&
                        rest[0].text.data() == name.text.data() + name.text.size();
  macro.body.assign(rest.begin(), rest.end());
  return macro;
}

// The text of a branch whose condition has `value`, in a group whose parent has `parent`.
Reach BranchReach(Reach parent, bool known, bool value) {
  if (parent == Reach::Skipped || (known && !value)) return Reach::Skipped;
  if (parent == Reach::Unknown || !known) return Reach::Unknown;
  return Reach::Active;
}

}  // namespace

// Evaluates one #if or #elif expression; nullopt when it cannot (a macro whose value is not
// known, a malformed expression: glslang reports the latter).
class GroupTracker::Condition {
 public:
  Condition(const GroupTracker& tracker, std::vector<Token>* undefined)
      : tracker_(tracker), undefined_(undefined) {}

  std::optional<long long> Evaluate(std::span<const Token> tokens) {
    if (!Expand(tokens, 0)) return std::nullopt;
    pos_ = 0;
    std::optional<long long> value = Binary(0);
    if (!value || pos_ != expanded_.size()) return std::nullopt;
    return value;
  }

 private:
  // Replaces 'defined X', 'defined ( X )' and macros; an identifier left is undefined and 0.
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
        Truth is_defined = tracker_.Defined(tokens[name].text);
        if (is_defined == Truth::Unknown) return false;
        expanded_.push_back({Token::Number, is_defined == Truth::True ? "1" : "0", t.offset});
        i = paren ? name + 1 : name;
        continue;
      }
      auto macro = tracker_.macros_.find(t.text);
      if (macro != tracker_.macros_.end()) {
        if (macro->second.function_like || macro->second.unsure) return false;
        std::vector<Token> body = JoinOperators(macro->second.body);
        for (Token& b : body) b.offset = t.offset;  // reported at the name in the directive
        if (!Expand(body, depth + 1)) return false;
        continue;
      }
      if (Predefined(t.text) || tracker_.MaybeMacro(t.text)) return false;
      undefined_->push_back(t);
      expanded_.push_back({Token::Number, "0", t.offset});
    }
    return true;
  }

  // Precedence of a binary operator (3.3's table, 1 = '||' lowest ... 10 = '*'), 0 if none.
  static int Precedence(std::string_view op) {
    static const std::map<std::string_view, int> table = {
        {"||", 1}, {"&&", 2}, {"|", 3}, {"^", 4},  {"&", 5},  {"==", 6},
        {"!=", 6}, {"<", 7},  {">", 7}, {"<=", 7}, {">=", 7}, {"<<", 8},
        {">>", 8}, {"+", 9},  {"-", 9}, {"*", 10}, {"/", 10}, {"%", 10}};
    auto it = table.find(op);
    return it == table.end() ? 0 : it->second;
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

  const GroupTracker& tracker_;
  std::vector<Token>* undefined_;
  std::vector<Token> expanded_;
  size_t pos_ = 0;
};

GroupTracker::GroupTracker(std::string_view preamble) : preamble_(BlankComments(preamble)) {
  for (const Directive& d : Directives(preamble_)) Follow(d);
}

bool GroupTracker::MaybeMacro(std::string_view name) const {
  // 3.3 reserves "GL_" names to the implementation, which defines one per extension it has
  // (glslang some of its own besides those of arbiter's preamble).
  return name.substr(0, 3) == "GL_" || included_;
}

FollowedDirective GroupTracker::Follow(const Directive& d) {
  FollowedDirective out;
  out.reach = reach();
  if (d.name == "if" || d.name == "ifdef" || d.name == "ifndef") {
    Open(d, &out);
  } else if (d.name == "elif" || d.name == "else" || d.name == "endif") {
    if (groups_.empty()) return out;  // unbalanced: glslang reports it
    out.reach = groups_.back().parent;
    Continue(d, &out);
  } else if (d.name == "define" || d.name == "undef") {
    Define(d);
  } else if (d.name == "include" && out.reach != Reach::Skipped) {
    // The included file may define any macro (and arbiter does not read it here).
    included_ = true;
  }
  return out;
}

// #if, #ifdef or #ifndef: a new group.
void GroupTracker::Open(const Directive& d, FollowedDirective* out) {
  const Reach parent = reach();
  if (parent == Reach::Skipped) {  // not evaluated, only counted for the nesting
    groups_.push_back({parent, Reach::Skipped, true, false});
    return;
  }
  Truth value = Truth::Unknown;
  if (d.name == "if") {
    value = Evaluate(d.words, parent == Reach::Active, out);
  } else if (!d.words.empty() && d.words[0].kind == Token::Identifier) {
    value = Defined(d.words[0].text);
    if (d.name == "ifndef" && value != Truth::Unknown) {
      value = value == Truth::True ? Truth::False : Truth::True;
    }
  }
  const bool known = value != Truth::Unknown;
  groups_.push_back(
      {parent, BranchReach(parent, known, value == Truth::True), value == Truth::True, !known});
}

// #elif, #else or #endif of the innermost group.
void GroupTracker::Continue(const Directive& d, FollowedDirective* out) {
  Group& g = groups_.back();
  if (d.name == "endif") {
    groups_.pop_back();
    return;
  }
  if (g.parent == Reach::Skipped || g.taken) {
    g.reach = Reach::Skipped;
    return;
  }
  Truth value = Truth::True;
  if (d.name == "elif") value = Evaluate(d.words, g.parent == Reach::Active && !g.maybe, out);
  // After a branch that may have been taken, this one is taken only perhaps.
  if (g.maybe && value == Truth::True) value = Truth::Unknown;
  const bool known = value != Truth::Unknown;
  g.taken = value == Truth::True;
  g.maybe = g.maybe || !known;
  g.reach = BranchReach(g.parent, known, value == Truth::True);
}

// #define and #undef count where the text is processed; where that is not known, the macro's
// value is not known either.
void GroupTracker::Define(const Directive& d) {
  const Reach here = reach();
  if (here == Reach::Skipped || d.words.empty() || d.words[0].kind != Token::Identifier) return;
  std::string name(d.words[0].text);
  if (d.name == "undef" && here == Reach::Active) {
    macros_.erase(name);
  } else if (d.name == "undef") {
    macros_[name] = Macro{false, true, {}};
  } else {
    Macro macro = MacroOf(d);
    macro.unsure = here == Reach::Unknown;
    macros_[name] = std::move(macro);
  }
}

GroupTracker::Truth GroupTracker::Defined(std::string_view name) const {
  auto it = macros_.find(name);
  if (it != macros_.end()) return it->second.unsure ? Truth::Unknown : Truth::True;
  if (Predefined(name)) return Truth::True;
  return MaybeMacro(name) ? Truth::Unknown : Truth::False;
}

GroupTracker::Truth GroupTracker::Evaluate(std::span<const Token> words, bool report,
                                           FollowedDirective* out) const {
  std::vector<Token> undefined;
  std::optional<long long> value = Condition(*this, &undefined).Evaluate(JoinOperators(words));
  if (report) out->undefined = std::move(undefined);
  if (!value) return Truth::Unknown;
  return *value != 0 ? Truth::True : Truth::False;
}

ShaderReach::ShaderReach(std::string_view preamble, std::span<const std::string_view> texts) {
  std::vector<std::string> blanked;  // the tracker's macros view them: destroyed after it
  blanked.reserve(texts.size());
  for (std::string_view text : texts) blanked.push_back(BlankComments(text));
  GroupTracker tracker(preamble);
  for (const std::string& text : blanked) {
    std::vector<std::pair<uint32_t, Reach>>& changes = changes_.emplace_back();
    changes.emplace_back(0, tracker.reach());
    for (const Directive& d : Directives(text)) {
      changes.emplace_back(d.hash, tracker.Follow(d).reach);
      changes.emplace_back(d.end, tracker.reach());
    }
  }
}

Reach ShaderReach::At(size_t index, uint32_t offset) const {
  const std::vector<std::pair<uint32_t, Reach>>& changes = changes_.at(index);
  auto after = std::ranges::upper_bound(
      changes, offset, {}, [](const std::pair<uint32_t, Reach>& c) { return c.first; });
  return std::prev(after)->second;
}

}  // namespace arbiter::glsl
