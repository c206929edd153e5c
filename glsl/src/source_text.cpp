// The text glslang is given (source_text.h). Every rewrite keeps the line of each token, and
// its column where it can: glslang's messages carry lines only, and the strictness layer
// checks that a location it reads from the AST names the token it expects.
#include "source_text.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <functional>
#include <set>
#include <vector>

#include "scan.h"

namespace arbiter::glsl {
namespace {

// Words that GLSL 1.10 does not reserve (3.6; the 1.10 change log: "the listed keywords and
// reserved words are the only ones") but glslang 12 does for every version, and the name
// glslang sees instead: as long, and containing "__", which 3.6 reserves, so no valid 1.10
// shader declares it (the strictness layer rejects a user's '__' name from the user's text).
struct Substitute {
  std::string_view word;
  std::string_view glslang;
};
constexpr Substitute kSubstitutes[] = {
    {"active", "ac____"}, {"case", "ca__"},           {"common", "co____"},
    {"filter", "fi____"}, {"partition", "pa_______"},
};

// Replaces each whole word of `text` that `replacement` gives a same-length word for (in
// place, so the scan goes on over the same buffer).
template <typename Replacement>
void ReplaceWords(std::string* text, Replacement replacement) {
  ForEachWord(*text, [&](size_t begin, size_t end) {
    std::string_view to = replacement(std::string_view(*text).substr(begin, end - begin));
    if (!to.empty()) text->replace(begin, to.size(), to);
  });
}

// The substitutes of kSubstitutes, to glslang's words or back.
void ReplaceWords(std::string* text, bool to_glslang) {
  ReplaceWords(text, [to_glslang](std::string_view word) -> std::string_view {
    for (const Substitute& sub : kSubstitutes) {
      if (word == (to_glslang ? sub.word : sub.glslang)) {
        return to_glslang ? sub.glslang : sub.word;
      }
    }
    return {};
  });
}

// The index of the token that closes the bracket opened at `open`; tokens.size() if none.
size_t Matching(const std::vector<Token>& tokens, size_t open) {
  char o = tokens[open].text[0];
  char c = o == '(' ? ')' : '}';
  int depth = 0;
  for (size_t i = open; i < tokens.size(); ++i) {
    if (tokens[i].text[0] == o && tokens[i].text.size() == 1) ++depth;
    if (tokens[i].text[0] == c && tokens[i].text.size() == 1 && --depth == 0) return i;
  }
  return tokens.size();
}

// The parameter names of the list between the parentheses at `open` and `close`: in each
// parameter, the last identifier before any '[', when the parameter has a type before it.
std::set<std::string_view> ParameterNames(const std::vector<Token>& tokens, size_t open,
                                          size_t close) {
  std::set<std::string_view> names;
  size_t words = 0;
  std::string_view last;
  bool in_size = false;
  for (size_t i = open + 1; i <= close; ++i) {
    std::string_view t = tokens[i].text;
    if (t == "," || i == close) {
      if (words >= 2) names.insert(last);
      words = 0;
      in_size = false;
    } else if (t == "[") {
      in_size = true;
    } else if (!in_size && IsIdentStart(t[0])) {
      ++words;
      last = t;
    }
  }
  return names;
}

// Keywords after which a name is an operand, not a declarator.
bool IsStatementKeyword(std::string_view t) { return t == "return" || t == "else" || t == "do"; }

// Whether the body between the braces at `open` and `close` declares one of `names` in its
// own scope: a name after a type (an identifier) or after a ',' outside parentheses and
// nested braces. A comma expression may match too: nesting the body is then harmless.
bool RedeclaresParameter(const std::vector<Token>& tokens, size_t open, size_t close,
                         const std::set<std::string_view>& names) {
  int braces = 0;
  int parens = 0;
  for (size_t i = open + 1; i < close; ++i) {
    std::string_view t = tokens[i].text;
    if (t == "{") ++braces;
    if (t == "}") --braces;
    if (t == "(" || t == "[") ++parens;
    if (t == ")" || t == "]") --parens;
    if (braces != 0 || parens != 0 || !names.count(t)) continue;
    std::string_view before = tokens[i - 1].text;
    if (before == "," || (IsIdentStart(before[0]) && !IsStatementKeyword(before))) return true;
  }
  return false;
}

// Adds `brace` next to the one at `at` with only white space between them: in place of a
// blank after it (or before it), else before the end of its line, else right after it
// (the one case that moves the rest of that line by a column).
void DoubleBrace(std::string* text, size_t at, char brace) {
  std::string& s = *text;
  auto blank = [&](size_t i) { return i < s.size() && (s[i] == ' ' || s[i] == '\t'); };
  if (blank(at + 1)) {
    s[at + 1] = brace;
  } else if (at > 0 && blank(at - 1)) {
    s[at - 1] = brace;
  } else {
    s.insert(at + 1, 1, brace);
  }
}

// GLSL 1.10 4.2: "A function body has a scope nested inside the function's definition", so
// a body may redeclare a parameter; glslang 12 (as GLSL 1.30) puts both in one scope. Each
// function body that redeclares a parameter gets a second pair of braces, which opens the
// nested scope 1.10 describes. Bodies are found at file level as a '{' after ')'; a text
// whose braces do not balance outside directives is left as it is.
void NestFunctionBodies(std::string* text) {
  std::vector<Token> tokens = Tokenize(*text);
  std::vector<std::pair<size_t, size_t>> bodies;  // offsets of '{' and '}'
  for (size_t i = 0; i < tokens.size(); ++i) {
    std::string_view t = tokens[i].text;
    if (t == "}") return;  // unbalanced
    if (t != "{") continue;
    size_t close = Matching(tokens, i);
    if (close == tokens.size()) return;
    if (i > 0 && tokens[i - 1].text == ")") {
      size_t open_paren = i - 1;
      int depth = 0;
      while (true) {
        if (tokens[open_paren].text == ")") ++depth;
        if (tokens[open_paren].text == "(" && --depth == 0) break;
        if (open_paren == 0) return;
        --open_paren;
      }
      std::set<std::string_view> names = ParameterNames(tokens, open_paren, i - 1);
      if (!names.empty() && RedeclaresParameter(tokens, i, close, names)) {
        bodies.emplace_back(tokens[i].offset, tokens[close].offset);
      }
    }
    i = close;
  }
  // From the end, so that an inserted brace moves no offset still to be used.
  std::reverse(bodies.begin(), bodies.end());
  for (const auto& [open, close] : bodies) {
    DoubleBrace(text, close, '}');
    DoubleBrace(text, open, '{');
  }
}

// glslang's preprocessor refuses a name past 1 024 characters ("name too long"); 1.10 sets no
// limit. Such a name becomes a short one of the same length (a hash of it, blank-padded), the
// same in every string, so columns and the program's meaning stay.
void ShortenLongNames(std::string* text) {
  constexpr size_t kLongest = 1000;
  for (size_t i = 0; i < text->size();) {
    const bool starts = IsIdentStart((*text)[i]) && (i == 0 || !IsIdentChar((*text)[i - 1]));
    if (!starts) {
      ++i;
      continue;
    }
    size_t end = i;
    while (end < text->size() && IsIdentChar((*text)[end])) ++end;
    if (end - i > kLongest) {
      const size_t hash = std::hash<std::string_view>{}(std::string_view(*text).substr(i, end - i));
      std::string name = fmt::format("{}{:016x}", kLongNamePrefix, hash);
      name.resize(end - i, ' ');
      text->replace(i, end - i, name);
    }
    i = end;
  }
}

// `varying struct S { ... };` and `attribute struct S { ... };` declare a type and no
// variable: 1.10's grammar takes a fully_specified_type without a declarator, and with no
// variable there is no varying or attribute of structure type (4.3.4, 4.3.6). glslang refuses
// a "vertex-shader struct output" there; without the qualifier it reads the same type.
void DropQualifierOfTypeOnlyStruct(std::string* text) {
  const std::vector<Token> tokens = Tokenize(*text);
  for (size_t i = 0; i + 3 < tokens.size(); ++i) {
    if ((tokens[i].text != "varying" && tokens[i].text != "attribute") ||
        tokens[i + 1].text != "struct" || tokens[i + 3].text != "{") {
      continue;
    }
    int depth = 0;
    size_t close = i + 3;
    for (; close < tokens.size(); ++close) {
      if (tokens[close].text == "{") ++depth;
      if (tokens[close].text == "}" && --depth == 0) break;
    }
    if (close + 1 < tokens.size() && tokens[close + 1].text == ";") {
      text->replace(tokens[i].offset, tokens[i].text.size(), tokens[i].text.size(), ' ');
    }
  }
}

}  // namespace

std::string PrepareForGlslang(std::string_view text) {
  std::string out(text);
  // 3.1 counts vertical tab and form feed as white space; glslang 12 rejects them. 3.1 ends
  // a line at a carriage return too; glslang 12 counts line feeds only, so a lone CR (old
  // Mac line ends) becomes a line feed: same length, and glslang's line numbers are 3.1's.
  for (size_t i = 0; i < out.size(); ++i) {
    char& c = out[i];
    if (c == '\v' || c == '\f') c = ' ';
    if (c == '\r' && (i + 1 == out.size() || out[i + 1] != '\n')) c = '\n';
  }
  ReplaceWords(&out, /*to_glslang=*/true);
  NestFunctionBodies(&out);
  ShortenLongNames(&out);
  DropQualifierOfTypeOnlyStruct(&out);
  return out;
}

std::string RestoreSpelling(std::string_view text, std::span<const Rename> renames) {
  std::string out(text);
  ReplaceWords(&out, [renames](std::string_view word) -> std::string_view {
    for (const Rename& r : renames) {
      if (word == r.glslang) return r.user;
    }
    return {};
  });
  ReplaceWords(&out, /*to_glslang=*/false);
  return out;
}

}  // namespace arbiter::glsl
