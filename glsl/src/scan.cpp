#include "scan.h"

#include <algorithm>

namespace arbiter::glsl {
namespace {

bool IsDigit(char c) { return c >= '0' && c <= '9'; }

// The end of a token starting at `i` (not blank, not a comment).
size_t TokenEnd(std::string_view text, size_t i, Token::Kind* kind) {
  const size_t start = i;
  char c = text[i];
  if (IsIdentStart(c)) {
    *kind = Token::Identifier;
    while (i < text.size() && IsIdentChar(text[i])) ++i;
    return i;
  }
  if (IsDigit(c) || (c == '.' && i + 1 < text.size() && IsDigit(text[i + 1]))) {
    *kind = Token::Number;
    while (i < text.size()) {
      char d = text[i];
      // An exponent's sign belongs to the number: 1.0e-5.
      bool hex = text.compare(start, 2, "0x") == 0 || text.compare(start, 2, "0X") == 0;
      bool sign = (d == '+' || d == '-') && (text[i - 1] == 'e' || text[i - 1] == 'E') && !hex;
      if (!IsIdentChar(d) && d != '.' && !sign) break;
      ++i;
    }
    return i;
  }
  *kind = Token::Punct;
  return i + 1;
}

}  // namespace

std::vector<Token> Tokenize(std::string_view text) {
  std::vector<Token> out;
  bool line_start = true;
  for (size_t i = 0; i < text.size();) {
    char c = text[i];
    if (c == '\n' || c == '\r') {  // 3.1: lines end at a carriage return too
      line_start = true;
      ++i;
    } else if (IsLineBlank(c)) {
      ++i;
    } else if (line_start && c == '#') {  // a directive runs to the end of its line
      while (i < text.size() && text[i] != '\n' && text[i] != '\r') ++i;
    } else if (text.compare(i, 2, "//") == 0) {
      while (i < text.size() && text[i] != '\n' && text[i] != '\r') ++i;
    } else if (text.compare(i, 2, "/*") == 0) {
      size_t end = text.find("*/", i + 2);
      // A comment counts as a blank: a '#' after it still starts a directive when only
      // blanks and comments precede it on the line.
      i = end == std::string_view::npos ? text.size() : end + 2;
    } else {
      line_start = false;
      Token::Kind kind;
      size_t end = TokenEnd(text, i, &kind);
      out.push_back({kind, text.substr(i, end - i), static_cast<uint32_t>(i)});
      i = end;
    }
  }
  return out;
}

std::string BlankComments(std::string_view text) {
  std::string out(text);
  for (size_t i = 0; i + 1 < out.size(); ++i) {
    if (out[i] == '/' && out[i + 1] == '/') {
      while (i < out.size() && out[i] != '\n' && out[i] != '\r') out[i++] = ' ';
    } else if (out[i] == '/' && out[i + 1] == '*') {
      out[i] = out[i + 1] = ' ';
      i += 2;
      while (i + 1 < out.size() && !(out[i] == '*' && out[i + 1] == '/')) {
        if (out[i] != '\n' && out[i] != '\r') out[i] = ' ';
        ++i;
      }
      if (i + 1 < out.size()) {
        out[i] = out[i + 1] = ' ';
      } else if (i < out.size() && out[i] != '\n') {
        out[i] = ' ';  // an unterminated comment runs to the end
      }
    }
  }
  return out;
}

std::vector<Directive> Directives(std::string_view blanked) {
  std::vector<Directive> out;
  bool code = false;
  int depth = 0;
  for (size_t line = 0; line <= blanked.size();) {
    size_t end = blanked.find_first_of("\r\n", line);  // a lone '\r' ends a line too
    if (end == std::string_view::npos) end = blanked.size();
    size_t pos = line;
    while (pos < end && IsLineBlank(blanked[pos])) ++pos;
    if (pos < end && blanked[pos] == '#') {
      Directive d;
      d.hash = static_cast<uint32_t>(pos);
      d.end = static_cast<uint32_t>(end);
      d.before_code = !code;
      d.brace_depth = depth;
      std::string_view rest = blanked.substr(pos + 1, end - pos - 1);
      std::vector<Token> tokens = Tokenize(rest);
      for (Token& t : tokens) t.offset += static_cast<uint32_t>(pos + 1);
      if (!tokens.empty() && tokens.front().kind == Token::Identifier) {
        d.name = tokens.front().text;
        d.name_offset = tokens.front().offset;
        tokens.erase(tokens.begin());
      }
      d.words = std::move(tokens);
      out.push_back(std::move(d));
    } else if (pos < end) {
      code = true;
      for (size_t i = pos; i < end; ++i) {
        if (blanked[i] == '{') ++depth;
        if (blanked[i] == '}' && depth > 0) --depth;
      }
    }
    line = end + 1;
  }
  return out;
}

std::vector<Token> JoinOperators(std::span<const Token> tokens) {
  static constexpr std::string_view kPairs[] = {"<<", ">>", "<=", ">=", "==", "!=", "&&", "||"};
  std::vector<Token> out;
  for (size_t i = 0; i < tokens.size(); ++i) {
    Token t = tokens[i];
    const bool touch = i + 1 < tokens.size() && t.kind == Token::Punct &&
                       tokens[i + 1].kind == Token::Punct &&
                       tokens[i + 1].text.data() == t.text.data() + 1;
    if (touch &&
        std::ranges::find(kPairs, std::string_view(t.text.data(), 2)) != std::end(kPairs)) {
      t.text = std::string_view(t.text.data(), 2);
      ++i;
    }
    out.push_back(t);
  }
  return out;
}

}  // namespace arbiter::glsl
