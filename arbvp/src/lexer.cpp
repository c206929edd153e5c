// The ARB program lexer: whitespace, '#' comments, identifiers, numbers, punctuation.
#include "lexer.h"

#include <fmt/format.h>

#include <array>

#include "diag.h"

namespace arbiter::arbvp {
namespace {

// Character classes, one table lookup per byte: lexing is a large share of checking, and
// the parser lexes the text a second time as it reads (see ReportLexicalErrors).
enum CharClass : uint8_t {
  kInvalid,
  kSpace,
  kComment,     // '#'
  kIdentStart,  // letters, '_', '$'
  kDigit,
  kDot,     // '.', which may begin '..' or a number
  kSingle,  // the one-character tokens , ; [ ] { } = + -
};

struct CharTables {
  std::array<CharClass, 256> classes{};
  std::array<Tok, 256> single{};  // the token of a kSingle character
};

constexpr CharTables MakeTables() {
  CharTables t;
  for (unsigned char c : {' ', '\t', '\n', '\r', '\f', '\v'}) t.classes[c] = kSpace;
  t.classes['#'] = kComment;
  for (int c = 'a'; c <= 'z'; ++c) t.classes[static_cast<size_t>(c)] = kIdentStart;
  for (int c = 'A'; c <= 'Z'; ++c) t.classes[static_cast<size_t>(c)] = kIdentStart;
  t.classes['_'] = kIdentStart;
  t.classes['$'] = kIdentStart;
  for (int c = '0'; c <= '9'; ++c) t.classes[static_cast<size_t>(c)] = kDigit;
  t.classes['.'] = kDot;
  const std::pair<unsigned char, Tok> singles[] = {
      {',', Tok::Comma},  {';', Tok::Semicolon}, {'[', Tok::LBracket}, {']', Tok::RBracket},
      {'{', Tok::LBrace}, {'}', Tok::RBrace},    {'=', Tok::Equals},   {'+', Tok::Plus},
      {'-', Tok::Minus},  {'|', Tok::Bar},       {':', Tok::Colon},    {'(', Tok::LParen},
      {')', Tok::RParen}};
  for (const auto& [c, tok] : singles) {
    t.classes[c] = kSingle;
    t.single[c] = tok;
  }
  return t;
}
constexpr CharTables kTables = MakeTables();

CharClass ClassOf(char c) { return kTables.classes[static_cast<unsigned char>(c)]; }
bool IsDigit(char c) { return ClassOf(c) == kDigit; }
// kIdentStart and kDigit are adjacent: one comparison.
bool IsIdentChar(char c) { return static_cast<uint8_t>(ClassOf(c) - kIdentStart) <= 1; }
bool IsValidStart(char c) { return ClassOf(c) != kInvalid; }
// A byte that continues a comment without a second look: not a line end, not NUL, ASCII.
bool IsPlainCommentByte(char c) {
  auto u = static_cast<unsigned char>(c);
  return u != '\n' && u != '\r' && u != 0 && u < 0x80;
}

std::string DescribeByte(unsigned char c) {
  if (c == 0) return "NUL byte";
  if (c < 0x20 || c == 0x7f) return fmt::format("control character 0x{:02X}", c);
  if (c >= 0x80) return fmt::format("non-ASCII byte 0x{:02X}", c);
  return fmt::format("'{}'", static_cast<char>(c));
}

}  // namespace

Lexer::Lexer(const compiler::SourceFile& source, uint32_t start, compiler::DiagnosticSink* sink)
    : source_(source),
      text_(source.text().c_str()),
      size_(static_cast<uint32_t>(source.text().size())),
      pos_(start),
      sink_(sink) {}

// Inlined into Next() and Fill(): a call per token is a large share of lexing.
[[gnu::always_inline]] inline Token Lexer::Lex1() {
  const char* const text = text_;
  uint32_t pos = pos_;
  for (;;) {
    CharClass c = ClassOf(text[pos]);
    while (c == kSpace) c = ClassOf(text[++pos]);  // stops at the terminating NUL
    if (pos >= size_) {
      pos_ = size_;
      return {Tok::Eof, size_, size_};
    }
    switch (c) {
      case kIdentStart: {
        uint32_t start = pos;
        do {
          ++pos;
        } while (IsIdentChar(text[pos]));
        pos_ = pos;
        return {Tok::Ident, start, pos};
      }
      case kSingle:
        pos_ = pos + 1;
        return {kTables.single[static_cast<unsigned char>(text[pos])], pos, pos + 1};
      case kDigit:
        pos_ = pos;
        return LexNumber();
      case kDot:
        // Past the last character is the NUL: neither a digit nor a '.'.
        if (IsDigit(text[pos + 1])) {
          pos_ = pos;
          return LexNumber();
        }
        if (text[pos + 1] == '.') {
          pos_ = pos + 2;
          return {Tok::DotDot, pos, pos + 2};
        }
        pos_ = pos + 1;
        return {Tok::Dot, pos, pos + 1};
      case kComment:
        pos_ = pos;
        SkipComment();
        pos = pos_;
        continue;
      case kSpace:
      case kInvalid:
        pos_ = pos;
        SkipInvalid();
        pos = pos_;
        continue;
    }
  }
}

Token Lexer::Next() { return Lex1(); }

size_t Lexer::Fill(Token* out, size_t count) {
  for (size_t n = 0; n < count; ++n) {
    out[n] = Lex1();
    if (out[n].kind == Tok::Eof) return n + 1;
  }
  return count;
}

// Skips a run of invalid bytes, reported once. Out of line: the hot loop of Next() stays
// small.
void Lexer::SkipInvalid() {
  uint32_t start = pos_;
  while (pos_ < size_ && !IsValidStart(text_[pos_])) ++pos_;
  if (sink_) {
    sink_->Report(Info(Diag::LexInvalidChar), &source_, {start, start + 1},
                  fmt::format("invalid character {} in program text",
                              DescribeByte(static_cast<unsigned char>(text_[start]))));
  }
}

// A comment ends at a newline, a carriage return or the end of the text.
void Lexer::SkipComment() {
  const char* const text = text_;
  uint32_t pos = pos_;
  for (;;) {
    // Plain ASCII other than the line ends (and the terminating NUL) needs no look.
    while (IsPlainCommentByte(text[pos])) ++pos;
    if (pos >= size_ || text[pos] == '\n' || text[pos] == '\r') break;
    if (static_cast<unsigned char>(text[pos]) >= 0x80 && !warned_non_ascii_) {
      warned_non_ascii_ = true;
      if (sink_) {
        sink_->Report(Info(Diag::LexNonAsciiComment), &source_, {pos, pos + 1},
                      "comment holds non-ASCII bytes; ARB program strings are 7-bit ASCII");
      }
    }
    ++pos;  // a non-ASCII byte or a NUL inside the text: part of the comment
  }
  pos_ = pos;
}

// <floatConstant>: digits, optional fraction, optional exponent; "1D" "2D" "3D" are the
// texture targets, lexed as identifiers.
Token Lexer::LexNumber() {
  // Reads past the end as NUL, which is neither a digit nor a letter.
  auto at = [&](uint32_t i) -> char { return i < size_ ? text_[i] : '\0'; };
  uint32_t pos = pos_;
  uint32_t start = pos;
  bool is_float = false;
  while (IsDigit(at(pos))) ++pos;
  // Texture targets 1D, 2D, 3D.
  if (pos == start + 1 && at(pos) == 'D' && !IsIdentChar(at(pos + 1))) {
    pos_ = pos + 1;
    return {Tok::Ident, start, pos_};
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
      if (sink_) {
        sink_->Report(Info(Diag::LexBadNumber), &source_, {start, exp},
                      fmt::format("malformed number '{}': the exponent needs digits",
                                  std::string_view(text_ + start, exp - start)));
      }
      while (IsIdentChar(at(exp))) ++exp;
      pos_ = exp;
      return {Tok::Float, start, exp};
    }
    while (IsDigit(at(exp))) ++exp;
    pos = exp;
    is_float = true;
  }
  pos_ = pos;
  return {is_float ? Tok::Float : Tok::Integer, start, pos};
}

std::vector<Token> Lex(const compiler::SourceFile& source, uint32_t start,
                       compiler::DiagnosticSink* sink) {
  std::vector<Token> tokens;
  Lexer lexer(source, start, sink);
  do {
    tokens.push_back(lexer.Next());
  } while (tokens.back().kind != Tok::Eof);
  return tokens;
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
    case Tok::Bar:
      return "'|'";
    case Tok::Colon:
      return "':'";
    case Tok::LParen:
      return "'('";
    case Tok::RParen:
      return "')'";
    case Tok::Eof:
      return "end of program";
  }
  return "token";
}

}  // namespace arbiter::arbvp
