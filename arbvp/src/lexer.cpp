// The ARB program lexer: whitespace, '#' comments, identifiers, numbers, punctuation.
#include "lexer.h"

#include <fmt/format.h>

#include "diag.h"

namespace arbiter::arbvp {
namespace {

bool IsIdentStart(unsigned char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c == '$';
}
bool IsDigit(unsigned char c) { return c >= '0' && c <= '9'; }
bool IsIdentChar(unsigned char c) { return IsIdentStart(c) || IsDigit(c); }

std::string DescribeByte(unsigned char c) {
  if (c == 0) return "NUL byte";
  if (c < 0x20 || c == 0x7f) return fmt::format("control character 0x{:02X}", c);
  if (c >= 0x80) return fmt::format("non-ASCII byte 0x{:02X}", c);
  return fmt::format("'{}'", static_cast<char>(c));
}

class Lexer {
 public:
  Lexer(const compiler::SourceFile& source, compiler::DiagnosticSink* sink)
      : source_(source), text_(source.text()), sink_(sink) {}

  std::vector<Token> Run(uint32_t pos) {
    std::vector<Token> tokens;
    const auto size = static_cast<uint32_t>(text_.size());
    bool warned_non_ascii = false;
    while (pos < size) {
      const auto c = static_cast<unsigned char>(text_[pos]);
      if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v') {
        ++pos;
        continue;
      }
      if (c == '#') {
        // A comment ends at a newline, a carriage return or the end of the text.
        while (pos < size && text_[pos] != '\n' && text_[pos] != '\r') {
          if (static_cast<unsigned char>(text_[pos]) >= 0x80 && !warned_non_ascii) {
            warned_non_ascii = true;
            sink_->Report(Info(Diag::LexNonAsciiComment), &source_, {pos, pos + 1},
                          "comment holds non-ASCII bytes; ARB program strings are 7-bit ASCII");
          }
          ++pos;
        }
        continue;
      }
      if (IsIdentStart(c)) {
        uint32_t start = pos;
        while (pos < size && IsIdentChar(static_cast<unsigned char>(text_[pos]))) ++pos;
        tokens.push_back({Tok::Ident, start, pos});
        continue;
      }
      if (IsDigit(c) ||
          (c == '.' && pos + 1 < size && IsDigit(static_cast<unsigned char>(text_[pos + 1])))) {
        pos = LexNumber(pos, &tokens);
        continue;
      }
      Tok kind = Tok::Eof;
      uint32_t len = 1;
      switch (c) {
        case '.':
          if (pos + 1 < size && text_[pos + 1] == '.') {
            kind = Tok::DotDot;
            len = 2;
          } else {
            kind = Tok::Dot;
          }
          break;
        case ',':
          kind = Tok::Comma;
          break;
        case ';':
          kind = Tok::Semicolon;
          break;
        case '[':
          kind = Tok::LBracket;
          break;
        case ']':
          kind = Tok::RBracket;
          break;
        case '{':
          kind = Tok::LBrace;
          break;
        case '}':
          kind = Tok::RBrace;
          break;
        case '=':
          kind = Tok::Equals;
          break;
        case '+':
          kind = Tok::Plus;
          break;
        case '-':
          kind = Tok::Minus;
          break;
        default:
          break;
      }
      if (kind == Tok::Eof) {
        // Report a run of invalid bytes once.
        uint32_t start = pos;
        while (pos < size && !IsValidStart(static_cast<unsigned char>(text_[pos]))) ++pos;
        sink_->Report(Info(Diag::LexInvalidChar), &source_, {start, start + 1},
                      fmt::format("invalid character {} in program text", DescribeByte(c)));
        continue;
      }
      tokens.push_back({kind, pos, pos + len});
      pos += len;
    }
    tokens.push_back({Tok::Eof, size, size});
    return tokens;
  }

 private:
  static bool IsValidStart(unsigned char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v' || c == '#' ||
           IsIdentChar(c) || c == '.' || c == ',' || c == ';' || c == '[' || c == ']' || c == '{' ||
           c == '}' || c == '=' || c == '+' || c == '-';
  }

  // <floatConstant>: digits, optional fraction, optional exponent; "1D" "2D" "3D" are the
  // texture targets, lexed as identifiers.
  uint32_t LexNumber(uint32_t pos, std::vector<Token>* tokens) {
    const auto size = static_cast<uint32_t>(text_.size());
    auto at = [&](uint32_t i) -> unsigned char {
      return i < size ? static_cast<unsigned char>(text_[i]) : 0;
    };
    uint32_t start = pos;
    bool is_float = false;
    while (IsDigit(at(pos))) ++pos;
    // Texture targets 1D, 2D, 3D.
    if (pos == start + 1 && at(pos) == 'D' && !IsIdentChar(at(pos + 1))) {
      tokens->push_back({Tok::Ident, start, pos + 1});
      return pos + 1;
    }
    // A fraction: '.' not followed by another '.' (that is the ".." of a range).
    if (at(pos) == '.' && at(pos + 1) != '.') {
      is_float = true;
      ++pos;
      while (IsDigit(at(pos))) ++pos;
    }
    if (at(pos) == 'e' || at(pos) == 'E') {
      uint32_t exp = pos + 1;
      if (at(exp) == '+' || at(exp) == '-') ++exp;
      if (!IsDigit(at(exp))) {
        sink_->Report(Info(Diag::LexBadNumber), &source_, {start, exp},
                      fmt::format("malformed number '{}': the exponent needs digits",
                                  text_.substr(start, exp - start)));
        while (IsIdentChar(at(exp))) ++exp;
        tokens->push_back({Tok::Float, start, exp});
        return exp;
      }
      while (IsDigit(at(exp))) ++exp;
      pos = exp;
      is_float = true;
    }
    tokens->push_back({is_float ? Tok::Float : Tok::Integer, start, pos});
    return pos;
  }

  const compiler::SourceFile& source_;
  std::string_view text_;
  compiler::DiagnosticSink* sink_;
};

}  // namespace

std::vector<Token> Lex(const compiler::SourceFile& source, uint32_t start,
                       compiler::DiagnosticSink* sink) {
  return Lexer(source, sink).Run(start);
}

std::string_view TokenKindName(Tok kind) {
  switch (kind) {
    case Tok::Ident:
      return "identifier";
    case Tok::Integer:
      return "integer";
    case Tok::Float:
      return "number";
    case Tok::Dot:
      return "'.'";
    case Tok::DotDot:
      return "'..'";
    case Tok::Comma:
      return "','";
    case Tok::Semicolon:
      return "';'";
    case Tok::LBracket:
      return "'['";
    case Tok::RBracket:
      return "']'";
    case Tok::LBrace:
      return "'{'";
    case Tok::RBrace:
      return "'}'";
    case Tok::Equals:
      return "'='";
    case Tok::Plus:
      return "'+'";
    case Tok::Minus:
      return "'-'";
    case Tok::Eof:
      return "end of program";
  }
  return "token";
}

}  // namespace arbiter::arbvp
