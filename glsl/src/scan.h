// The one scanner of GLSL text that arbiter's own rules read (the directives, the tokens of a
// declaration): identifiers, numbers and punctuation, with comments skipped and preprocessor
// lines apart. glslang has the real preprocessor; this reads the text as written, before macro
// expansion, which is what the rules of chapter 3 and the declaration checks are about.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace arbiter::glsl {

inline bool IsIdentStart(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
inline bool IsIdentChar(char c) { return IsIdentStart(c) || (c >= '0' && c <= '9'); }
// Blanks within a line (3.1: space, tab, vertical tab, form feed; carriage returns too).
inline bool IsLineBlank(char c) {
  return c == ' ' || c == '\t' || c == '\v' || c == '\f' || c == '\r';
}

// Calls `f(begin, end)` for each run of identifier characters (a name or a number) of `text`.
template <typename F>
void ForEachWord(std::string_view text, F f) {
  for (size_t i = 0; i < text.size();) {
    if (!IsIdentChar(text[i])) {
      ++i;
      continue;
    }
    const size_t begin = i;
    while (i < text.size() && IsIdentChar(text[i])) ++i;
    f(begin, i);
  }
}

struct Token {
  enum Kind : uint8_t { Identifier, Number, Punct };
  Kind kind;
  std::string_view text;
  uint32_t offset;  // in the scanned text
};

// The tokens of `text` outside comments and preprocessor lines: identifiers, numbers (with
// their suffixes and exponents) and single punctuation characters.
std::vector<Token> Tokenize(std::string_view text);

// The text with comments replaced by blanks (newlines kept), so offsets stay valid.
std::string BlankComments(std::string_view text);

// One preprocessor line of a comment-blanked text: `# name words...`.
struct Directive {
  uint32_t hash = 0;      // offset of '#'
  uint32_t end = 0;       // offset of the line's end (its '\r' or '\n', or the text's end)
  std::string_view name;  // "version", "extension", "" for a null directive
  uint32_t name_offset = 0;
  std::vector<Token> words;  // the tokens after the name
  bool before_code = true;   // no token outside a directive came before it in this text
  int brace_depth = 0;       // depth of '{' outside directives where it starts
};

// Every directive of a comment-blanked text, in order; their views point into `blanked`.
// Continuation lines ('\' before the newline) are not joined: GLSL 1.10 and 1.20 have none (3.1
// and 3.3).
std::vector<Directive> Directives(std::string_view blanked);

// `tokens` with each two-character operator of a #if expression ("<<", ">>", "<=", ">=", "==",
// "!=", "&&", "||") joined into one Punct token, left to right. Two tokens join only when they
// touch in the text, so "< <" stays apart; the tokens must view one text (a Tokenize or a
// Directive's words).
std::vector<Token> JoinOperators(std::span<const Token> tokens);

}  // namespace arbiter::glsl
