#include "syntax_error.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <string>

#include "scan.h"

namespace arbiter::glsl {
namespace {

// glslang's grammar names of operators and punctuation (glslang.y), and their text.
struct Punctuation {
  std::string_view name;
  std::string_view text;
};
constexpr std::array<Punctuation, 45> kPunctuation{{
    {"LEFT_ASSIGN", "<<="}, {"RIGHT_ASSIGN", ">>="}, {"LEFT_OP", "<<"},    {"RIGHT_OP", ">>"},
    {"INC_OP", "++"},       {"DEC_OP", "--"},        {"LE_OP", "<="},      {"GE_OP", ">="},
    {"EQ_OP", "=="},        {"NE_OP", "!="},         {"AND_OP", "&&"},     {"OR_OP", "||"},
    {"XOR_OP", "^^"},       {"MUL_ASSIGN", "*="},    {"DIV_ASSIGN", "/="}, {"ADD_ASSIGN", "+="},
    {"MOD_ASSIGN", "%="},   {"AND_ASSIGN", "&="},    {"XOR_ASSIGN", "^="}, {"OR_ASSIGN", "|="},
    {"SUB_ASSIGN", "-="},   {"LEFT_PAREN", "("},     {"RIGHT_PAREN", ")"}, {"LEFT_BRACKET", "["},
    {"RIGHT_BRACKET", "]"}, {"LEFT_BRACE", "{"},     {"RIGHT_BRACE", "}"}, {"DOT", "."},
    {"COMMA", ","},         {"COLON", ":"},          {"EQUAL", "="},       {"SEMICOLON", ";"},
    {"BANG", "!"},          {"DASH", "-"},           {"TILDE", "~"},       {"PLUS", "+"},
    {"STAR", "*"},          {"SLASH", "/"},          {"PERCENT", "%"},     {"LEFT_ANGLE", "<"},
    {"RIGHT_ANGLE", ">"},   {"VERTICAL_BAR", "|"},   {"CARET", "^"},       {"AMPERSAND", "&"},
    {"QUESTION", "?"},
}};

bool IsNumberName(std::string_view name) {
  return name == "INTCONSTANT" || name == "UINTCONSTANT" || name == "FLOATCONSTANT" ||
         name == "DOUBLECONSTANT";
}

bool EqualsIgnoringCase(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) ==
                  std::tolower(static_cast<unsigned char>(y));
         });
}

// Whether `token` is what the grammar name stands for: an identifier (or a structure's type
// name), a number, true/false, or a keyword (FLOAT is `float`, SAMPLER2D `sampler2D`).
bool Matches(const Token& token, std::string_view name) {
  if (name == "IDENTIFIER" || name == "TYPE_NAME") return token.kind == Token::Identifier;
  if (IsNumberName(name)) return token.kind == Token::Number;
  if (name == "BOOLCONSTANT") return token.text == "true" || token.text == "false";
  return token.kind == Token::Identifier && EqualsIgnoringCase(token.text, name);
}

bool EndsOperand(const Token& token) {
  return token.kind == Token::Number || token.kind == Token::Identifier || token.text == ")" ||
         token.text == "]";
}

}  // namespace

std::optional<SyntaxErrorPlace> LocateSyntaxError(const compiler::SourceFile& file, uint32_t line,
                                                  std::string_view message) {
  constexpr std::string_view kUnexpected = "unexpected ";
  const size_t at = message.find(kUnexpected);
  if (at == std::string_view::npos || line < 1 || line > file.line_count()) return std::nullopt;
  std::string_view name = message.substr(at + kUnexpected.size());
  name = name.substr(0, name.find_first_of(", "));

  const std::string blanked = BlankComments(file.text());
  const uint32_t start = file.LineStart(line);
  const std::string_view text = std::string_view(blanked).substr(start, file.LineText(line).size());
  std::optional<compiler::Range> found;
  for (const Punctuation& p : kPunctuation) {
    if (p.name != name) continue;
    size_t pos = text.find(p.text);
    // A closing bracket is unexpected where it has no opening one on the line; else the first.
    if (p.text == ")" || p.text == "]" || p.text == "}") {
      const char open = p.text == ")" ? '(' : p.text == "]" ? '[' : '{';
      int depth = 0;
      for (size_t i = 0; i < text.size(); ++i) {
        if (text[i] == open) ++depth;
        if (text[i] == p.text[0] && --depth < 0) {
          pos = i;
          break;
        }
      }
    }
    if (pos != std::string_view::npos) {
      const auto begin = static_cast<uint32_t>(start + pos);
      found = compiler::Range{begin, static_cast<uint32_t>(begin + p.text.size())};
    }
  }
  const std::vector<Token> tokens = Tokenize(text);
  if (!found) {
    // Of the tokens of that kind, the parser most likely stopped at one that follows a whole
    // operand (`vec4(1.0) 2.0`: the 2.0) or opens the line; else the first.
    const Token* first = nullptr;
    const Token* best = nullptr;
    for (size_t i = 0; i < tokens.size() && best == nullptr; ++i) {
      if (!Matches(tokens[i], name)) continue;
      if (first == nullptr) first = &tokens[i];
      if (i == 0 || EndsOperand(tokens[i - 1])) best = &tokens[i];
    }
    if (best == nullptr) best = first;
    if (best != nullptr) {
      const uint32_t begin = start + best->offset;
      found = compiler::Range{begin, static_cast<uint32_t>(begin + best->text.size())};
    }
  }
  if (!found) return std::nullopt;
  SyntaxErrorPlace place{*found, std::nullopt};

  // A ';' was expected and the token opens its line: the previous statement lacks its ';'.
  const bool wants_semicolon = message.find("expecting") != std::string_view::npos &&
                               message.find("SEMICOLON") != std::string_view::npos;
  const bool first_on_line = !tokens.empty() && start + tokens.front().offset == found->begin;
  if (wants_semicolon && first_on_line) {
    const std::vector<Token> before = Tokenize(std::string_view(blanked).substr(0, start));
    if (!before.empty()) {
      const Token& last = before.back();
      const auto end = static_cast<uint32_t>(last.offset + last.text.size());
      place.missing_semicolon = compiler::Range{end, end};
    }
  }
  return place;
}

}  // namespace arbiter::glsl
