// MakeProbe: the shaders with each hazard (glsl::FindHazards) wrapped in a function that
// notes the hazard kind and site when its operands make the result undefined and returns
// the same value, main() renamed and wrapped so that the outputs start at a sentinel and
// the findings leave through one more output. Edits are insertions at byte offsets (and the
// renaming of gl_FragColor), so nested hazards compose.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <set>

#include "glsl_verify/internal.h"

namespace arbiter::runtime::glsl_verify {
namespace {

// ---- Tokens -------------------------------------------------------------------------------

struct Token {
  uint32_t begin = 0;
  uint32_t end = 0;
  std::string_view text;
};

bool IsIdentStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0 || c == '_'; }
bool IsIdentChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

// The tokens of `text` (comments and preprocessor lines skipped; a number with its exponent
// and suffix as one).
std::vector<Token> Tokenize(std::string_view text) {
  static const std::vector<std::string_view> kTwo = {
      "++", "--", "+=", "-=", "*=", "/=", "==", "!=", "<=", ">=", "&&", "||", "^^", "<<", ">>"};
  std::vector<Token> out;
  size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (std::isspace(static_cast<unsigned char>(c)) != 0 || c == '\\') {
      ++i;
    } else if (c == '#' &&
               (i == 0 || text.find_last_not_of(" \t", i - 1) == text.rfind('\n', i - 1))) {
      // A preprocessor line (continued lines included): not the shader's tokens.
      while (i < text.size() && text[i] != '\n') i += text[i] == '\\' ? 2 : 1;
    } else if (text.substr(i, 2) == "//") {
      i = text.find('\n', i);
      if (i == std::string_view::npos) i = text.size();
    } else if (text.substr(i, 2) == "/*") {
      i = text.find("*/", i + 2);
      i = i == std::string_view::npos ? text.size() : i + 2;
    } else if (IsIdentStart(c)) {
      size_t j = i;
      while (j < text.size() && IsIdentChar(text[j])) ++j;
      out.push_back({static_cast<uint32_t>(i), static_cast<uint32_t>(j), text.substr(i, j - i)});
      i = j;
    } else if (std::isdigit(static_cast<unsigned char>(c)) != 0 ||
               (c == '.' && i + 1 < text.size() &&
                std::isdigit(static_cast<unsigned char>(text[i + 1])) != 0)) {
      size_t j = i;
      while (j < text.size() &&
             (IsIdentChar(text[j]) || text[j] == '.' ||
              ((text[j] == '+' || text[j] == '-') && (text[j - 1] == 'e' || text[j - 1] == 'E')))) {
        ++j;
      }
      out.push_back({static_cast<uint32_t>(i), static_cast<uint32_t>(j), text.substr(i, j - i)});
      i = j;
    } else {
      size_t n = 1;
      for (std::string_view two : kTwo) {
        if (text.substr(i, 2) == two) n = 2;
      }
      out.push_back({static_cast<uint32_t>(i), static_cast<uint32_t>(i + n), text.substr(i, n)});
      i += n;
    }
  }
  return out;
}

class Scanner {
 public:
  explicit Scanner(const std::vector<Token>& tokens) : t_(tokens) {}

  // The token starting at byte `offset`; npos when none does.
  size_t At(uint32_t offset) const {
    auto it = std::lower_bound(t_.begin(), t_.end(), offset,
                               [](const Token& t, uint32_t o) { return t.begin < o; });
    return it != t_.end() && it->begin == offset ? static_cast<size_t>(it - t_.begin()) : npos;
  }
  bool Is(size_t i, std::string_view text) const { return i < t_.size() && t_[i].text == text; }
  bool Ident(size_t i) const { return i < t_.size() && IsIdentStart(t_[i].text[0]); }
  // The bracket matching the opening one at `i`; npos when unbalanced.
  size_t Match(size_t i) const {
    if (i >= t_.size()) return npos;
    const std::string_view open = t_[i].text;
    const std::string_view close = open == "(" ? ")" : open == "[" ? "]" : "}";
    int depth = 0;
    for (size_t j = i; j < t_.size(); ++j) {
      if (t_[j].text == open) ++depth;
      if (t_[j].text == close && --depth == 0) return j;
    }
    return npos;
  }
  // One past a unary expression starting at `i` (GLSL 1.20 section 5.x's grammar: prefix
  // operators, a primary expression or constructor or call, postfix selectors); npos when
  // the tokens are not one.
  size_t Unary(size_t i) const {
    while (Is(i, "-") || Is(i, "+") || Is(i, "!") || Is(i, "~") || Is(i, "++") || Is(i, "--")) {
      ++i;
    }
    size_t j;
    if (Is(i, "(")) {
      j = Match(i);
      if (j == npos) return npos;
      ++j;
    } else if (Ident(i) ||
               (i < t_.size() && std::isdigit(static_cast<unsigned char>(t_[i].text[0])) != 0) ||
               (i < t_.size() && t_[i].text[0] == '.')) {
      j = i + 1;
      if (Ident(i) && Is(j, "[")) {  // float[3](...): an array constructor
        const size_t close = Match(j);
        if (close != npos && Is(close + 1, "(")) j = close + 1;
      }
      if (Ident(i) && Is(j, "(")) {
        j = Match(j);
        if (j == npos) return npos;
        ++j;
      }
    } else {
      return npos;
    }
    for (;;) {
      if (Is(j, "[")) {
        j = Match(j);
        if (j == npos) return npos;
        ++j;
      } else if (Is(j, ".") && Ident(j + 1)) {
        j += 2;
      } else if (Is(j, "++") || Is(j, "--")) {
        ++j;
      } else {
        return j;
      }
    }
  }
  // One past the assignment expression starting at `i`: up to a ';' or ',' at its depth, or
  // the bracket that closes around it.
  size_t Assignment(size_t i) const {
    int depth = 0;
    for (size_t j = i; j < t_.size(); ++j) {
      const std::string_view s = t_[j].text;
      if (s == "(" || s == "[" || s == "{") ++depth;
      if (s == ")" || s == "]" || s == "}") {
        if (depth == 0) return j;
        --depth;
      }
      if ((s == ";" || s == ",") && depth == 0) return j;
    }
    return npos;
  }
  const Token& operator[](size_t i) const { return t_[i]; }
  size_t size() const { return t_.size(); }
  static constexpr size_t npos = static_cast<size_t>(-1);

 private:
  const std::vector<Token>& t_;
};

// ---- Edits --------------------------------------------------------------------------------

struct Edit {
  uint32_t offset = 0;
  int order = 0;    // at one offset: closing texts (0), opening texts (1), replacements (2)
  int64_t key = 0;  // closes: inner (shorter) first; opens: outer (longer) first
  uint32_t erase = 0;
  std::string text;
};

void Wrap(uint32_t begin, uint32_t end, std::string open, std::string close,
          std::vector<Edit>* edits) {
  const auto span = static_cast<int64_t>(end - begin);
  edits->push_back({begin, 1, -span, 0, std::move(open)});
  edits->push_back({end, 0, span, 0, std::move(close)});
}

std::string Apply(std::string_view text, std::vector<Edit> edits) {
  std::stable_sort(edits.begin(), edits.end(), [](const Edit& a, const Edit& b) {
    return std::tie(a.offset, a.order, a.key) < std::tie(b.offset, b.order, b.key);
  });
  std::string out;
  uint32_t at = 0;
  for (const Edit& e : edits) {
    if (e.offset < at) continue;  // inside a replaced token: cannot happen for valid edits
    out.append(text.substr(at, e.offset - at));
    out += e.text;
    at = e.offset + e.erase;
  }
  out.append(text.substr(at));
  return out;
}

// ---- Helpers (GLSL 1.10: no bit operations, so kinds add up as powers of two in a float) --

struct TypeShape {
  const char* name;
  int columns;  // matrices: column vectors; 0 otherwise
  int size;     // components (per column)
};
constexpr TypeShape kFloatTypes[] = {
    {"float", 0, 1}, {"vec2", 0, 2}, {"vec3", 0, 3}, {"vec4", 0, 4}};
constexpr TypeShape kIntTypes[] = {
    {"int", 0, 1}, {"ivec2", 0, 2}, {"ivec3", 0, 3}, {"ivec4", 0, 4}};
constexpr TypeShape kMatTypes[] = {{"mat2", 2, 2}, {"mat3", 3, 3}, {"mat4", 4, 4}};

// Each component of `var` of shape `t`: "x", "x.y", "x[1].z".
std::vector<std::string> Components(const std::string& var, const TypeShape& t) {
  std::vector<std::string> out;
  auto vec = [&](const std::string& v, int size) {
    if (size == 1) {
      out.push_back(v);
      return;
    }
    for (int c = 0; c < size; ++c) out.push_back(fmt::format("{}.{}", v, "xyzw"[c]));
  };
  if (t.columns == 0) {
    vec(var, t.size);
  } else {
    for (int c = 0; c < t.columns; ++c) vec(fmt::format("{}[{}]", var, c), t.size);
  }
  return out;
}

// "(a.x < 0.0 || a.y < 0.0)" for a condition template over the components, `$a`/`$b` standing
// for component i of the arguments named a and b.
std::string AnyOf(const TypeShape& t, const std::vector<std::string>& args,
                  const std::string& condition) {
  std::vector<std::vector<std::string>> comps;
  for (const std::string& a : args) comps.push_back(Components(a, t));
  std::vector<std::string> terms;
  for (size_t i = 0; i < comps[0].size(); ++i) {
    std::string term = condition;
    for (size_t a = 0; a < args.size(); ++a) {
      const std::string key = "$" + args[a];
      for (size_t at = term.find(key); at != std::string::npos; at = term.find(key)) {
        term.replace(at, key.size(), comps[a][i]);
      }
    }
    terms.push_back("(" + term + ")");
  }
  return fmt::format("({})", fmt::join(terms, " || "));
}

float Bit(glsl::HazardKind kind) { return static_cast<float>(1u << static_cast<unsigned>(kind)); }

// The wrappers of the hazard kinds in `kinds`, every overload GLSL 1.20 has for them.
std::string Helpers(const std::set<glsl::HazardKind>& kinds, bool vertex) {
  std::string out = fmt::format(
      "float arb_probe_bits;\nfloat arb_probe_site;\nuniform float {};\n"
      "uniform mat4 {};\nuniform mat3 {};\n{}"
      "void arb_probe_mark(float bit, float site) {{\n"
      "  if (mod(floor(arb_probe_bits / bit), 2.0) < 0.5) arb_probe_bits += bit;\n"
      "  if (arb_probe_site < 0.0) arb_probe_site = site;\n}}\n",
      kSentinelUniform, kNudge4Uniform, kNudge3Uniform,
      vertex ? fmt::format("varying vec4 {};\n", kProbeVarying) : "");
  using glsl::HazardKind;
  auto one = [&](HazardKind kind, const std::string& result, const std::string& name,
                 const std::string& params, const std::string& bad, const std::string& call) {
    out += fmt::format(
        "{} arb_probe_{}({}, float s) {{\n  if {} arb_probe_mark({:.1f}, s);\n  return {};\n}}\n",
        result, name, params, bad, Bit(kind), call);
  };
  for (HazardKind kind : kinds) {
    for (const TypeShape& t : kFloatTypes) {
      const std::string T = t.name;
      const bool vec = t.size > 1;
      switch (kind) {
        case HazardKind::Division:
          one(kind, T, "div", T + " b", AnyOf(t, {"b"}, "$b == 0.0"), "b");
          break;
        case HazardKind::Mod:
          one(kind, T, "mod", T + " x, " + T + " y", AnyOf(t, {"y"}, "$y == 0.0"), "mod(x, y)");
          if (vec) one(kind, T, "mod", T + " x, float y", "(y == 0.0)", "mod(x, y)");
          break;
        case HazardKind::Pow:
          one(kind, T, "pow", T + " x, " + T + " y",
              AnyOf(t, {"x", "y"}, "$x < 0.0 || ($x == 0.0 && $y <= 0.0)"), "pow(x, y)");
          break;
        case HazardKind::Log:
          one(kind, T, "log", T + " x", AnyOf(t, {"x"}, "$x <= 0.0"), "log(x)");
          one(kind, T, "log2", T + " x", AnyOf(t, {"x"}, "$x <= 0.0"), "log2(x)");
          break;
        case HazardKind::Sqrt:
          one(kind, T, "sqrt", T + " x", AnyOf(t, {"x"}, "$x < 0.0"), "sqrt(x)");
          break;
        case HazardKind::InverseSqrt:
          one(kind, T, "inversesqrt", T + " x", AnyOf(t, {"x"}, "$x <= 0.0"), "inversesqrt(x)");
          break;
        case HazardKind::AsinAcos:
          one(kind, T, "asin", T + " x", AnyOf(t, {"x"}, "abs($x) > 1.0"), "asin(x)");
          one(kind, T, "acos", T + " x", AnyOf(t, {"x"}, "abs($x) > 1.0"), "acos(x)");
          break;
        case HazardKind::Atan:
          one(kind, T, "atan", T + " y, " + T + " x",
              AnyOf(t, {"x", "y"}, "$x == 0.0 && $y == 0.0"), "atan(y, x)");
          break;
        case HazardKind::Normalize:
          one(kind, T, "normalize", T + " x", "(!" + AnyOf(t, {"x"}, "$x != 0.0") + ")",
              "normalize(x)");
          break;
        case HazardKind::Clamp:
          one(kind, T, "clamp", T + " x, " + T + " lo, " + T + " hi",
              AnyOf(t, {"lo", "hi"}, "$lo > $hi"), "clamp(x, lo, hi)");
          if (vec) {
            one(kind, T, "clamp", T + " x, float lo, float hi", "(lo > hi)", "clamp(x, lo, hi)");
          }
          break;
        case HazardKind::Smoothstep:
          one(kind, T, "smoothstep", T + " e0, " + T + " e1, " + T + " x",
              AnyOf(t, {"e0", "e1"}, "$e0 >= $e1"), "smoothstep(e0, e1, x)");
          if (vec) {
            one(kind, T, "smoothstep", "float e0, float e1, " + T + " x", "(e0 >= e1)",
                "smoothstep(e0, e1, x)");
          }
          break;
        case HazardKind::Index:
        case HazardKind::Projection:
        case HazardKind::CubeFace:
          break;  // below: not one of the float types'
      }
    }
    if (kind == HazardKind::Division) {
      for (const TypeShape& t : kIntTypes) {
        one(kind, t.name, "div", std::string(t.name) + " b", AnyOf(t, {"b"}, "$b == 0"), "b");
      }
      for (const TypeShape& t : kMatTypes) {
        one(kind, t.name, "div", std::string(t.name) + " b", AnyOf(t, {"b"}, "$b == 0.0"), "b");
      }
    }
    if (kind == HazardKind::Index) {
      one(kind, "int", "index", "int i, int n", "(i < 0 || i >= n)", "i");
    }
    if (kind == HazardKind::CubeFace) {
      // The two largest magnitudes equal (all zero, no direction at all, is a tie too).
      one(kind, "vec3", "cube", "vec3 c",
          "((abs(c.x) == abs(c.y) && abs(c.x) >= abs(c.z)) || (abs(c.x) == abs(c.z) && "
          "abs(c.x) >= abs(c.y)) || (abs(c.y) == abs(c.z) && abs(c.y) >= abs(c.x)))",
          "c");
    }
    if (kind == HazardKind::Projection) {
      one(kind, "vec2", "proj", "vec2 c", "(c.y == 0.0)", "c");
      one(kind, "vec3", "proj", "vec3 c", "(c.z == 0.0)", "c");
      one(kind, "vec4", "proj", "vec4 c", "(c.w == 0.0)", "c");
    }
  }
  return out;
}

// ---- Outputs and variables ----------------------------------------------------------------

// The sentinel as a value of basic type `type` (integers and booleans differ between the
// two sentinels too); "" for a type it cannot make.
std::string SentinelValue(const std::string& type) {
  const std::string s = kSentinelUniform;
  const int n = type.empty() ? 0 : type.back() - '0';
  if (type == "float") return fmt::format("float({})", s);
  if (type == "int") return fmt::format("int({} * 16.0)", s);
  if (type == "bool") return fmt::format("({} > 0.5)", s);
  if (n < 2 || n > 4) return "";
  if (type == fmt::format("vec{}", n)) return fmt::format("vec{}({})", n, s);
  if (type == fmt::format("ivec{}", n)) return fmt::format("ivec{}(int({} * 16.0))", n, s);
  if (type == fmt::format("bvec{}", n)) return fmt::format("bvec{}({} > 0.5)", n, s);
  if (type == fmt::format("mat{}", n)) {
    std::vector<std::string> columns(static_cast<size_t>(n), fmt::format("vec{}({})", n, s));
    return fmt::format("mat{}({})", n, fmt::join(columns, ", "));
  }
  return "";
}

// A structure's members: (name, type, elements: 0 for no array, -1 for a size that is no
// literal).
struct Member {
  std::string name;
  std::string type;
  int elements = 0;
};
using Structs = std::map<std::string, std::vector<Member>, std::less<>>;

// The declarators of a declaration whose type ends before token `j` (names with their array
// sizes, those with an initializer marked), up to its ';'; `*end` the ';'.
struct Declarator {
  size_t token = 0;
  int elements = 0;
  bool initialized = false;
};
std::vector<Declarator> Declarators(const Scanner& scan, size_t j, size_t* end) {
  std::vector<Declarator> out;
  *end = Scanner::npos;
  while (scan.Ident(j)) {
    Declarator d{j, 0, false};
    size_t next = j + 1;
    if (scan.Is(next, "[")) {
      const size_t close = scan.Match(next);
      if (close == Scanner::npos) return out;
      // An integer literal (decimal, octal or hexadecimal, as GLSL 1.10 section 4.1.3 writes
      // them); anything else: not known here.
      d.elements =
          close == next + 2
              ? static_cast<int>(std::strtol(std::string(scan[next + 1].text).c_str(), nullptr, 0))
              : -1;
      if (d.elements <= 0) d.elements = -1;
      next = close + 1;
    }
    if (scan.Is(next, "=")) {
      d.initialized = true;
      next = scan.Assignment(next + 1);
      if (next == Scanner::npos) return out;
    }
    out.push_back(d);
    if (!scan.Is(next, ",")) {
      if (scan.Is(next, ";")) *end = next;
      return out;
    }
    j = next + 1;
  }
  return out;
}

// The structures the shader defines, by name (not one defined twice, in nested scopes:
// which one a declaration means is not known here).
Structs StructsOf(const Scanner& scan) {
  Structs out;
  std::set<std::string> twice;
  for (size_t i = 0; i + 2 < scan.size(); ++i) {
    if (scan[i].text != "struct") continue;
    // A nameless structure is known by its brace: "@<token>".
    const bool named = scan.Ident(i + 1) && scan.Is(i + 2, "{");
    const size_t open = named ? i + 2 : i + 1;
    if (!scan.Is(open, "{")) continue;
    const size_t close = scan.Match(open);
    if (close == Scanner::npos) continue;
    const std::string name = named ? std::string(scan[i + 1].text) : fmt::format("@{}", open);
    if (out.count(name) > 0) twice.insert(name);
    std::vector<Member>& members = out[name];
    for (size_t k = open + 1; k < close;) {
      size_t end = Scanner::npos;
      for (const Declarator& d : Declarators(scan, k + 1, &end)) {
        members.push_back({std::string(scan[d.token].text), std::string(scan[k].text), d.elements});
      }
      if (end == Scanner::npos) break;
      k = end + 1;
    }
  }
  for (const std::string& name : twice) out.erase(name);
  return out;
}

// Statements setting `var` of type `type` to the sentinel, member by member and element by
// element; none for what has no sentinel (an array of unknown size, an unknown type).
void SentinelAssignments(const std::string& var, const std::string& type, int elements,
                         const Structs& structs, int level, std::string* out) {
  if (elements < 0 || level > 8) return;
  if (elements > 0) {
    for (int e = 0; e < elements; ++e) {
      SentinelAssignments(fmt::format("{}[{}]", var, e), type, 0, structs, level + 1, out);
    }
    return;
  }
  const std::string value = SentinelValue(type);
  if (!value.empty()) {
    *out += fmt::format("{} = {}; ", var, value);
    return;
  }
  auto it = structs.find(type);
  if (it == structs.end()) return;
  for (const Member& m : it->second) {
    SentinelAssignments(var + "." + m.name, m.type, m.elements, structs, level + 1, out);
  }
}

// Variables declared without an initializer, which a path may read before writing: each is
// set to the sentinel right after its declaration (a local: an initializer, or statements
// after its ';'), or from the wrapper's main (a global, whose initializer must be constant:
// the statements returned).
std::string UninitializedVariables(const Scanner& scan, std::vector<Edit>* edits) {
  static const std::set<std::string_view> kQualifiers = {
      "const", "uniform", "varying", "attribute", "in", "out", "inout", "invariant", "centroid"};
  const Structs structs = StructsOf(scan);
  std::string globals;
  int depth = 0;
  std::vector<bool> bodies;  // per open brace: a structure's body (members, not variables)
  for (size_t i = 0; i < scan.size(); ++i) {
    const std::string_view t = scan[i].text;
    if (t == "{") {
      ++depth;
      bodies.push_back((i > 0 && scan.Is(i - 1, "struct")) || (i > 1 && scan.Is(i - 2, "struct")));
    }
    if (t == "}") {
      --depth;
      if (!bodies.empty()) bodies.pop_back();
    }
    if (std::find(bodies.begin(), bodies.end(), true) != bodies.end()) continue;
    const bool for_init = scan.Is(i - 1, "(") && i > 1 && scan.Is(i - 2, "for");
    const bool start =
        i == 0 || scan.Is(i - 1, ";") || scan.Is(i - 1, "{") || scan.Is(i - 1, "}") || for_init;
    if (!start || (i > 0 && kQualifiers.count(scan[i - 1].text) > 0)) continue;
    // The type: a basic type, a structure's name, or a structure defined here.
    std::string type(t);
    size_t first = i + 1;
    if (t == "struct") {
      const bool named = scan.Ident(i + 1) && scan.Is(i + 2, "{");
      const size_t open = named ? i + 2 : i + 1;
      if (!scan.Is(open, "{")) continue;
      type = named ? std::string(scan[i + 1].text) : fmt::format("@{}", open);
      first = scan.Match(open);
      if (first == Scanner::npos) continue;
      ++first;
    } else if (SentinelValue(type).empty() && structs.find(type) == structs.end()) {
      continue;
    }
    if (!scan.Ident(first) || scan.Is(first + 1, "(")) continue;  // none, or a function
    size_t end = Scanner::npos;
    const std::vector<Declarator> declarators = Declarators(scan, first, &end);
    std::string after;  // a local's statements after its declaration
    for (const Declarator& d : declarators) {
      if (d.initialized) continue;
      const std::string name(scan[d.token].text);
      const std::string value = SentinelValue(type);
      if (depth > 0 && d.elements == 0 && !value.empty()) {
        edits->push_back({scan[d.token].end, 1, 0, 0, " = " + value});
      } else if (depth > 0 && !for_init) {
        SentinelAssignments(name, type, d.elements, structs, 0, &after);
      } else if (depth == 0) {
        SentinelAssignments(name, type, d.elements, structs, 0, &globals);
      }
    }
    if (!after.empty() && end != Scanner::npos) {
      edits->push_back({scan[end].end, 1, 0, 0, " " + after});
    }
  }
  std::string out;
  if (!globals.empty()) out = "  " + globals + "\n";
  return out;
}

// Statements that set every output the stage writes to the sentinel.
std::string SentinelWrites(const glsl::Reflection& r,
                           const std::map<std::string, std::string>& renamed) {
  std::string out;
  const std::string s = kSentinelUniform;
  auto value = [&](const std::string& type) {
    const std::string v = SentinelValue(type);
    return v.empty() ? fmt::format("{}({})", type, s) : v;
  };
  for (const glsl::BuiltinUse& b : r.builtins_written) {
    const bool scalar =
        b.name == "gl_PointSize" || b.name == "gl_FogFragCoord" || b.name == "gl_FragDepth";
    const std::string type = scalar ? "float" : "vec4";
    auto it = renamed.find(b.name);
    const std::string name = it != renamed.end() ? it->second : b.name;
    if ((b.name == "gl_TexCoord" || b.name == "gl_FragData") && b.components >= 4) {
      for (int i = 0; i < b.components / 4; ++i)
        out += fmt::format("  {}[{}] = vec4({});\n", name, i, s);
    } else if (b.name.find('.') == std::string::npos) {
      out += fmt::format("  {} = {};\n", name, value(type));
    }
  }
  for (const glsl::ReflectedVariable& v : r.varyings) {
    if (!v.written) continue;
    if (v.array_size > 0) {
      for (int i = 0; i < v.array_size; ++i)
        out += fmt::format("  {}[{}] = {};\n", v.name, i, value(v.type));
    } else {
      out += fmt::format("  {} = {};\n", v.name, value(v.type));
    }
  }
  return out;
}

// Where the helpers go: before the shader's first token outside any #if (after #version,
// #extension and the like), on that token's line, so that no line moves (a shader may test
// __LINE__, and arbiter's checker reads diagnostics' lines back). npos when there is none.
uint32_t HelperOffset(std::string_view text, const Scanner& scan) {
  // The #if depth at the start of each line.
  std::vector<int> depth_at;
  int depth = 0;
  for (size_t line = 0; line <= text.size();) {
    depth_at.push_back(depth);
    size_t end = text.find('\n', line);
    if (end == std::string_view::npos) end = text.size();
    std::string_view l = text.substr(line, end - line);
    const size_t first = l.find_first_not_of(" \t");
    if (first != std::string_view::npos && l[first] == '#') {
      std::string_view d = l.substr(first + 1);
      d.remove_prefix(std::min(d.find_first_not_of(" \t"), d.size()));
      if (d.starts_with("if")) ++depth;  // #if, #ifdef, #ifndef
      if (d.starts_with("endif")) --depth;
    }
    line = end + 1;
  }
  for (size_t i = 0; i < scan.size(); ++i) {
    const auto line =
        static_cast<size_t>(std::count(text.begin(), text.begin() + scan[i].begin, '\n'));
    if (line < depth_at.size() && depth_at[line] == 0) return scan[i].begin;
  }
  return static_cast<uint32_t>(text.size());
}

// Whether token `i` lies in a const declaration, whose initializer must stay a constant
// expression (no call of a wrapper).
bool InConstDeclaration(const Scanner& scan, size_t i) {
  while (i > 0 && !scan.Is(i - 1, ";") && !scan.Is(i - 1, "{") && !scan.Is(i - 1, "}")) --i;
  return scan.Is(i, "const");
}

// The instrumented text of one stage; false (with `why`) when a hazard cannot be wrapped.
bool InstrumentStage(glsl::Stage stage, const compiler::SourceFile& file,
                     const glsl::Reflection& reflection, Probe* probe, std::string* text,
                     std::string* why) {
  const std::string_view source = file.text();
  const std::vector<Token> tokens = Tokenize(source);
  const Scanner scan(tokens);
  std::vector<Edit> edits;
  std::set<glsl::HazardKind> kinds;
  const std::vector<const compiler::SourceFile*> sources{&file};
  for (const glsl::Hazard& h : glsl::FindHazards(stage, sources)) {
    if (h.file != &file) continue;  // a macro's expansion: not instrumented
    const size_t i = scan.At(h.range.begin);
    if (i == Scanner::npos || InConstDeclaration(scan, i)) continue;
    const auto site = static_cast<int>(probe->sites.size());
    const std::string tail = fmt::format(", {}.0)", site);
    bool placed = false;
    if (h.kind == glsl::HazardKind::Division && (scan.Is(i, "/") || scan.Is(i, "/="))) {
      const size_t end = scan.Is(i, "/=") ? scan.Assignment(i + 1) : scan.Unary(i + 1);
      if (end != Scanner::npos && end > i + 1) {
        Wrap(scan[i + 1].begin, scan[end - 1].end, "arb_probe_div(", tail, &edits);
        placed = true;
      }
    } else if (h.kind == glsl::HazardKind::Index && scan.Is(i, "[")) {
      const size_t close = scan.Match(i);
      if (close != Scanner::npos && close > i + 1) {
        Wrap(scan[i + 1].begin, scan[close].begin, "arb_probe_index((",
             fmt::format("), {}, {}.0)", h.size, site), &edits);
        placed = true;
      }
    } else if ((h.kind == glsl::HazardKind::Projection || h.kind == glsl::HazardKind::CubeFace) &&
               scan.Is(i + 1, "(")) {
      // The coordinates: the second argument, between the first two commas of the call.
      const size_t close = scan.Match(i + 1);
      size_t first = Scanner::npos;
      size_t second = close;
      int depth = 0;
      for (size_t j = i + 2; close != Scanner::npos && j < close; ++j) {
        if (scan.Is(j, "(") || scan.Is(j, "[")) ++depth;
        if (scan.Is(j, ")") || scan.Is(j, "]")) --depth;
        if (depth != 0 || !scan.Is(j, ",")) continue;
        if (first == Scanner::npos) {
          first = j;
        } else {
          second = j;
          break;
        }
      }
      if (first != Scanner::npos && second != Scanner::npos && second > first + 1) {
        Wrap(scan[first + 1].begin, scan[second - 1].end,
             h.kind == glsl::HazardKind::CubeFace ? "arb_probe_cube(" : "arb_probe_proj(", tail,
             &edits);
        placed = true;
      }
    } else if (scan.Ident(i) && scan.Is(i + 1, "(")) {
      const size_t close = scan.Match(i + 1);
      if (close != Scanner::npos) {
        Wrap(scan[i].begin, scan[close].begin, "arb_probe_", fmt::format(", {}.0", site), &edits);
        placed = true;
      }
    }
    if (!placed) continue;
    kinds.insert(h.kind);
    probe->sites.push_back(h);
  }
  // Every built-in state matrix read through the nudge (not in a const initializer, which
  // cannot read uniforms anyway).
  for (size_t i = 0; i < scan.size(); ++i) {
    const std::string_view t = scan[i].text;
    if (!t.starts_with("gl_") || t.find("Matrix") == std::string_view::npos) continue;
    if ((i > 0 && scan.Is(i - 1, ".")) || InConstDeclaration(scan, i)) continue;
    size_t last = i;  // the matrix: gl_TextureMatrix* with its index, the others alone
    if (t.starts_with("gl_TextureMatrix")) {
      if (!scan.Is(i + 1, "[")) continue;  // the array not indexed here: no matrix
      last = scan.Match(i + 1);
      if (last == Scanner::npos) continue;
    }
    const char* nudge = t == "gl_NormalMatrix" ? kNudge3Uniform : kNudge4Uniform;
    Wrap(scan[i].begin, scan[last].end, "matrixCompMult(", fmt::format(", {})", nudge), &edits);
  }
  // What the shader reads whose value is the implementation's to choose.
  std::set<std::string> constants;
  for (size_t i = 0; i < scan.size(); ++i) {
    if (scan[i].text.rfind("gl_Max", 0) == 0) constants.insert(std::string(scan[i].text));
    // glslang and Mesa fold a division by a literal zero before anything runs, each to its
    // own value: no site to wrap, but a cause all the same.
    if ((scan[i].text == "/" || scan[i].text == "/=") && i + 1 < scan.size() &&
        std::isdigit(static_cast<unsigned char>(scan[i + 1].text.back())) != 0 &&
        std::strtod(std::string(scan[i + 1].text).c_str(), nullptr) == 0.0) {
      probe->static_causes.insert(
          "a division by the constant zero (GLSL 1.10 section 4.1.4: undefined)");
    }
    if (scan[i].text == "dFdx" || scan[i].text == "dFdy" || scan[i].text == "fwidth") {
      // One point per vector: a derivative is taken across the quad's helper invocations,
      // by a method and to an accuracy the implementation chooses.
      probe->static_causes.insert(
          "a derivative (GLSL 1.10 section 8.8: its method and accuracy are the "
          "implementation's)");
    }
    if (scan[i].text == "gl_PointCoord") {
      probe->static_causes.insert(
          "gl_PointCoord outside a point sprite (GL 2.0 section 3.3.1: undefined)");
    }
  }
  if (!constants.empty()) {
    probe->static_causes.insert(fmt::format(
        "implementation-dependent constants ({}: GLSL 1.10 section 7.4 gives minimums only)",
        fmt::join(constants, ", ")));
  }
  // main() becomes arb_probe_main(); gl_FragColor gl_FragData[0].
  bool has_main = false;
  for (size_t i = 0; i + 1 < scan.size(); ++i) {
    if (scan[i].text == "main" && scan.Is(i + 1, "(") && i > 0 && scan.Is(i - 1, "void")) {
      edits.push_back({scan[i].begin, 1, 0, 0, "arb_probe_"});
      has_main = true;
    }
    if (scan[i].text == "gl_FragColor") {
      edits.push_back({scan[i].begin, 2, 0, scan[i].end - scan[i].begin, "gl_FragData[0]"});
      probe->renamed["gl_FragColor"] = "gl_FragData[0]";
    }
  }
  if (!has_main) {
    *why = "no main() to wrap";
    return false;
  }
  const bool vertex = stage == glsl::Stage::Vertex;
  if (!vertex) {
    for (size_t i = 0; i + 1 < scan.size(); ++i) {
      if (scan[i].text == "varying" && scan.Is(i + 1, "out")) {
        *why =
            "the shader declares outputs of its own (EXT_gpu_shader4), beside which "
            "gl_FragData cannot be written";
        return false;
      }
    }
    for (const glsl::BuiltinUse& b : reflection.builtins_written) {
      if (b.name == "gl_FragData" || b.name == kProbeFragData) {
        *why = "the shader writes gl_FragData[7] or indexes gl_FragData by a variable";
        return false;
      }
    }
  }
  const std::string globals = UninitializedVariables(scan, &edits);
  // The helpers on one line of their own text, before the first token.
  std::string helpers = Helpers(kinds, vertex);
  std::replace(helpers.begin(), helpers.end(), '\n', ' ');
  edits.push_back({HelperOffset(source, scan), -1, 0, 0, helpers});
  *text = Apply(source, std::move(edits));
  *text += fmt::format(
      "\nvoid main() {{\n  arb_probe_bits = 0.0;\n  arb_probe_site = -1.0;\n{}{}"
      "  arb_probe_main();\n  {} = vec4(arb_probe_bits, arb_probe_site, 0.0, 0.0);\n}}\n",
      SentinelWrites(reflection, probe->renamed), globals, vertex ? kProbeVarying : kProbeFragData);
  return true;
}

}  // namespace

Probe MakeProbe(const GlslVerifySubject& subject) {
  Probe probe;
  if (subject.vertex != nullptr &&
      !InstrumentStage(glsl::Stage::Vertex, *subject.vertex, *subject.vertex_reflection, &probe,
                       &probe.vertex, &probe.why)) {
    return probe;
  }
  if (subject.fragment != nullptr &&
      !InstrumentStage(glsl::Stage::Fragment, *subject.fragment, *subject.fragment_reflection,
                       &probe, &probe.fragment, &probe.why)) {
    return probe;
  }
  probe.ok = true;
  return probe;
}

ProbeFinding ReadProbe(const GlslVectorResult& result) {
  ProbeFinding f;
  for (const GlslOutput& o : result.outputs) {
    if ((o.name != kProbeVarying && o.name != kProbeFragData) || o.value.size() < 2) continue;
    f.known = true;
    f.kinds |= static_cast<unsigned>(o.value[0]);
    if (f.site < 0 && o.value[1] >= 0.0f) f.site = static_cast<int>(o.value[1]);
  }
  return f;
}

std::string DescribeFinding(const ProbeFinding& finding, const Probe& probe) {
  std::vector<std::string> kinds;
  for (const glsl::HazardInfo& info : glsl::AllHazards()) {
    if ((finding.kinds & (1u << static_cast<unsigned>(info.kind))) == 0) continue;
    kinds.push_back(fmt::format("{} ({})", info.what, info.spec));
  }
  std::string out = fmt::format("{}", fmt::join(kinds, "; "));
  if (finding.site >= 0 && static_cast<size_t>(finding.site) < probe.sites.size()) {
    const glsl::Hazard& h = probe.sites[static_cast<size_t>(finding.site)];
    const compiler::LineCol lc = h.file->Locate(h.range.begin);
    out += fmt::format(", first at {}:{}:{}", h.file->path(), lc.line, lc.column);
  }
  return out;
}

}  // namespace arbiter::runtime::glsl_verify
