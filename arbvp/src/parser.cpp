// Recursive-descent parser of ARB vertex and fragment programs (ARBvp 2.14.2, ARBfp 3.11.2).
// One function per grammar symbol, its production quoted above it. On an error the
// statement is abandoned and parsing resumes after the next ';': the parse functions report
// the error and return false, and their callers return false at once (no exceptions: a
// corpus with invalid programs threw hundreds per pass, a fifth of the time of checking).
#include "parser.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>

#include "arbiter/compiler/suggest.h"
#include "diag.h"
#include "flat_table.h"
#include "flow.h"
#include "nv_syntax.h"

namespace arbiter::arbvp {

using compiler::ClosestMatch;
using compiler::JoinAlternatives;
namespace {

using compiler::DiagnosticSink;
using compiler::SourceFile;

// A <floatConstant>'s value, rounded to nearest as strtof (what Mesa's lexer uses) rounds it.
// from_chars rounds the same and needs no NUL-terminated copy of the text; the values it
// leaves unset (out of range: overflow, underflow) go to strtof, which gives +inf on
// overflow, as GL would.
float ParseFloatText(std::string_view text) {
  // Fast path (Clinger's): digits with at most ten after the point and no exponent, whose
  // digits read as an integer m below 2^24. m and 10^k are exact floats, and IEEE division
  // rounds their exact quotient to nearest, as strtof does: the same float, without
  // from_chars' general algorithm (a large share of parsing constant-heavy programs).
  static constexpr float kPow10[] = {1e0f, 1e1f, 1e2f, 1e3f, 1e4f, 1e5f,
                                     1e6f, 1e7f, 1e8f, 1e9f, 1e10f};
  if (text.size() <= 12) {
    uint64_t m = 0;            // 12 digits at most: no overflow
    int fraction_digits = -1;  // -1: no point yet
    bool simple = !text.empty();
    for (char c : text) {
      if (c >= '0' && c <= '9') {
        m = m * 10 + static_cast<uint64_t>(c - '0');
        if (fraction_digits >= 0) ++fraction_digits;
      } else if (c == '.' && fraction_digits < 0) {
        fraction_digits = 0;
      } else {
        simple = false;
        break;
      }
    }
    if (simple && m < (uint64_t{1} << 24) && fraction_digits <= 10) {
      return static_cast<float>(m) / kPow10[fraction_digits < 0 ? 0 : fraction_digits];
    }
  }
  float value = 0.0f;
  auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec == std::errc()) return value;
  std::string copy(text);
  return std::strtof(copy.c_str(), nullptr);
}

// True when a number's mantissa (before any exponent) has a digit other than 0: a number
// that reads as zero only because it underflows.
bool HasNonZeroDigit(std::string_view text) {
  for (char c : text) {
    if (c == 'e' || c == 'E') break;
    if (c >= '1' && c <= '9') return true;
  }
  return false;
}

// s == word, always inlined: the parser compares words per token, and GCC leaves
// std::string_view's operator== out of line in this file (a call and a memcmp call per test;
// with a literal `word` the inlined memcmp is a load and a compare).
[[gnu::always_inline]] inline bool Is(std::string_view s, std::string_view word) {
  return s.size() == word.size() && std::memcmp(s.data(), word.data(), word.size()) == 0;
}

// Lets the symbol table be searched with a string_view (no allocation per lookup). FNV-1a:
// names are short, and a lookup per operand makes the general-purpose hash show in profiles.
struct StringHash {
  using is_transparent = void;
  size_t operator()(std::string_view s) const {
    uint64_t hash = 14695981039346656037ull;
    for (char c : s) hash = (hash ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    return static_cast<size_t>(hash);
  }
};

struct Symbol {
  int var = -1;  // -1: poisoned (its declaration failed)
  Range decl;    // the declared name: the symbol's key is this range of the text
};

// The declared names. Entries point into the program text, which outlives the parser: no
// string and no node per declared name (limit tests declare hundreds).
class SymbolTable {
 public:
  explicit SymbolTable(std::string_view text) : text_(text) {}

  const Symbol* Find(std::string_view name) const {
    return table_.Find(StringHash{}(name),
                       [&](const Symbol& s) { return SameName(NameOf(s), name); });
  }
  bool Contains(std::string_view name) const { return Find(name) != nullptr; }
  // Declares the name at `decl` as `var`; an existing entry is replaced when `replace`.
  void Declare(Range decl, int var, bool replace) {
    std::string_view name = NameOf(decl);
    bool inserted = false;
    Symbol* s = table_.FindOrInsert(
        StringHash{}(name), [&](const Symbol& e) { return SameName(NameOf(e), name); }, &inserted);
    if (inserted || replace) *s = {var, decl};
  }
  // Every declared name, in no particular order.
  std::vector<std::string_view> Names() const {
    std::vector<std::string_view> names;
    names.reserve(table_.size());
    table_.ForEach([&](const Symbol& s) { names.push_back(NameOf(s)); });
    return names;
  }

 private:
  // Names are a few characters: a loop beats a call to memcmp.
  static bool SameName(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i) {
      if (a[i] != b[i]) return false;
    }
    return true;
  }
  std::string_view NameOf(Range r) const {
    return std::string_view(text_.data() + r.begin, r.end - r.begin);  // a token's bounds
  }
  std::string_view NameOf(const Symbol& s) const { return NameOf(s.decl); }

  std::string_view text_;
  FlatTable<Symbol> table_;
};

constexpr std::string_view kVpKeywords[] = {"ADDRESS", "ALIAS",  "ATTRIB", "END",
                                            "OPTION",  "OUTPUT", "PARAM",  "TEMP",
                                            "program", "result", "state",  "vertex"};
constexpr std::string_view kFpKeywords[] = {"ALIAS",   "ATTRIB", "END",   "OPTION",
                                            "OUTPUT",  "PARAM",  "TEMP",  "fragment",
                                            "program", "result", "state", "texture"};
// For each first character, the lengths of the keywords that begin with it (bit n: n
// characters): IsReservedWord compares a word with the keywords only when one may match.
struct KeywordLengths {
  std::array<uint16_t, 128> by_first{};
};
template <size_t N>
constexpr KeywordLengths MakeKeywordLengths(const std::string_view (&keywords)[N]) {
  KeywordLengths lengths;
  for (std::string_view k : keywords) {
    lengths.by_first[static_cast<size_t>(k[0])] |= static_cast<uint16_t>(1u << k.size());
  }
  return lengths;
}
constexpr KeywordLengths kVpKeywordLengths = MakeKeywordLengths(kVpKeywords);
constexpr KeywordLengths kFpKeywordLengths = MakeKeywordLengths(kFpKeywords);
// IsReservedWord rejects other lengths without a look (and the masks hold 16 bits).
constexpr bool KeywordSizesIn3To8() {
  for (std::string_view k : kVpKeywords) {
    if (k.size() < 3 || k.size() > 8) return false;
  }
  for (std::string_view k : kFpKeywords) {
    if (k.size() < 3 || k.size() > 8) return false;
  }
  return true;
}
static_assert(KeywordSizesIn3To8());

// The variables no statement declares, the relatively addressed attribute and result arrays
// and NV_fragment_program2's A0, come into being at their first use; they are moved after the
// others, in that order, so that a printed program (which declares the others first) parses
// back with the same numbering.
void MoveUndeclaredLast(Program* program) {
  auto undeclared = [&](const Variable& v) {
    return v.relative_array ||
           (program->kind == ProgramKind::Fragment && v.kind == VarKind::Address);
  };
  const size_t n = program->vars.size();
  std::vector<int> to(n);
  int next = 0;
  for (int pass = 0; pass < 2; ++pass) {
    for (size_t v = 0; v < n; ++v) {
      if (undeclared(program->vars[v]) == (pass == 1)) to[v] = next++;
    }
  }
  if (std::is_sorted(to.begin(), to.end())) return;
  std::vector<Variable> vars(n);
  for (size_t v = 0; v < n; ++v) vars[static_cast<size_t>(to[v])] = std::move(program->vars[v]);
  program->vars = std::move(vars);
  auto renumber = [&](int* var) {
    if (*var >= 0 && static_cast<size_t>(*var) < n) *var = to[static_cast<size_t>(*var)];
  };
  for (Instruction& inst : program->instructions) {
    renumber(&inst.dst.var);
    renumber(&inst.dst.address_var);
    for (SrcOperand& src : inst.src) {
      renumber(&src.var);
      renumber(&src.address_var);
    }
  }
}

class Parser {
 public:
  // The parser lexes as it goes, keeping only a window of tokens (see ReportLexicalErrors).
  Parser(const SourceFile& source, ProgramKind kind, Range header, DiagnosticSink* sink)
      : source_(source),
        text_(source.text()),
        lexer_(source, header.end, sink),
        kind_(kind),
        sink_(sink),
        symbols_(text_) {}

  std::unique_ptr<Program> Run(Range header) {
    program_ = std::make_unique<Program>();
    program_->kind = kind_;
    program_->header = header;
    // Room for a typical program, so that it does not grow (and move) its arrays step by step.
    program_->vars.reserve(kTypicalStatements);
    program_->instructions.reserve(kTypicalStatements);
    last_end_ = header.end;
    ParseProgram();
    ReportLexicalErrors();  // those after END
    if (program_->Nv()) {
      ResolveFlow(program_.get(), source_, [this](Diag diag, Range range, std::string message) {
        return ReportDiagnostic(diag, range, std::move(message));
      });
      MoveUndeclaredLast(program_.get());
    }
    return std::move(program_);
  }

 private:
  bool vp() const { return kind_ == ProgramKind::Vertex; }
  bool fp() const { return kind_ == ProgramKind::Fragment; }

  // ---- tokens -------------------------------------------------------------------------

  // Every lexical error comes before the first parser diagnostic, in text order, as when the
  // whole text was lexed before parsing: the lexer reports what it meets as the parser
  // reads, and before the parser reports anything (or when it stops) a copy of the lexer
  // lexes the rest of the text for its errors alone. The parser's lexer is silent from then
  // on. Lexing the text twice only for programs with errors keeps checking fast, and
  // reading tokens as they come keeps no program-sized token array in memory.
  void ReportLexicalErrors() {
    if (lexical_errors_reported_) return;
    lexical_errors_reported_ = true;
    Lexer rest = lexer_;
    while (rest.Next().kind != Tok::Eof) {
    }
    lexer_.Silence();
  }
  compiler::Diagnostic* ReportDiagnostic(Diag diag, Range range, std::string message) {
    ReportLexicalErrors();
    return sink_->Report(Info(diag), &source_, range, std::move(message));
  }

  // Token pos_ + ahead; Eof past the end. A reference stays valid until a few tokens later.
  // The token helpers below are always inlined: they run several times per token.
  [[gnu::always_inline]] const Token& Peek(size_t ahead = 0) {
    size_t i = pos_ + ahead;
    if (i >= fetched_) [[unlikely]]
      Fetch(i);
    return window_[i % kWindow];
  }
  // Lexes up to token i (or Eof), and on as far as the window allows: lexing a batch of
  // tokens per call keeps the call out of most Peeks. Past the Eof token come copies of it,
  // so that Peek needs no bounds check.
  [[gnu::noinline]] void Fetch(size_t i) {
    size_t last = std::max(i, pos_ + kWindow - 3);  // keeps tokens pos_ - 2 on intact
    while (fetched_ <= last) {
      size_t slot = fetched_ % kWindow;
      if (fetched_ > eof_index_) {
        window_[slot] = window_[eof_index_ % kWindow];  // an Eof token (copies included)
        ++fetched_;
        continue;
      }
      size_t count = std::min(last + 1 - fetched_, kWindow - slot);  // contiguous slots
      size_t got = lexer_.Fill(&window_[slot], count);
      fetched_ += got;
      if (window_[slot + got - 1].kind == Tok::Eof) eof_index_ = fetched_ - 1;
    }
  }
  std::string_view Text(const Token& t) const {
    return std::string_view(text_.data() + t.begin, t.end - t.begin);  // the lexer's bounds
  }
  [[gnu::always_inline]] bool PeekIs(Tok kind, size_t ahead = 0) {
    return Peek(ahead).kind == kind;
  }
  bool PeekIdent(std::string_view word, size_t ahead = 0) {
    return Peek(ahead).kind == Tok::Ident && Is(Text(Peek(ahead)), word);
  }
  [[gnu::always_inline]] Token Advance() {
    Token t = Peek();
    if (pos_ < eof_index_) ++pos_;
    last_end_ = t.end;
    return t;
  }
  [[gnu::always_inline]] bool Accept(Tok kind) {
    if (!PeekIs(kind)) return false;
    Advance();
    return true;
  }
  static Range RangeOf(const Token& t) { return {t.begin, t.end}; }

  std::string Describe(const Token& t) const {
    if (t.kind == Tok::Eof) return "end of program";
    std::string_view s = Text(t);
    if (s.size() > 40) return fmt::format("'{}...'", s.substr(0, 40));
    return fmt::format("'{}'", s);
  }

  static std::string Quoted(std::string_view word) {
    return word.empty() ? std::string() : fmt::format("'{}' ", word);
  }
  // Reports an error that abandons the statement; returns false, for the callers to return
  // at once up to ParseProgram, which resynchronises. The parse functions fill their output
  // in place: after a failure it is partly written, and the statement's callers drop it.
  [[nodiscard]] bool Fail(Diag diag, Range range, std::string message) {
    ReportDiagnostic(diag, range, std::move(message));
    return false;
  }
  void Report(Diag diag, Range range, std::string message) {
    ReportDiagnostic(diag, range, std::move(message));
  }
  [[nodiscard]] bool FailExpected(std::string_view what) {
    const Token& t = Peek();
    return Fail(Diag::SyntaxExpected, RangeOf(t),
                fmt::format("expected {}, found {}", what, Describe(t)));
  }
  // Consumes the next token into *out (when given).
  [[gnu::always_inline]] bool Take(Token* out) {
    Token t = Advance();
    if (out) *out = t;
    return true;
  }
  [[nodiscard, gnu::always_inline]] bool Expect(Tok kind, std::string_view what,
                                                Token* out = nullptr) {
    if (!PeekIs(kind)) return FailExpected(what);
    return Take(out);
  }
  [[nodiscard, gnu::always_inline]] bool ExpectIdent(std::string_view what, Token* out) {
    return Expect(Tok::Ident, what, out);
  }
  // Expects one of `words` (an identifier); reports the alternatives otherwise.
  [[nodiscard]] bool ExpectWord(std::initializer_list<std::string_view> word_list,
                                std::string_view context, Token* out = nullptr) {
    const Token& t = Peek();
    if (t.kind == Tok::Ident) {
      for (std::string_view w : word_list) {
        if (Is(Text(t), w)) return Take(out);
      }
    }
    return ExpectWordSlow(std::vector<std::string_view>(word_list), context, out);
  }
  [[nodiscard]] bool ExpectWordSlow(const std::vector<std::string_view>& words,
                                    std::string_view context, Token* out) {
    const Token& t = Peek();
    if (t.kind == Tok::Ident) {
      for (std::string_view w : words) {
        if (Is(Text(t), w)) return Take(out);
      }
      std::string hint = ClosestMatch(Text(t), words);
      return Fail(
          Diag::BindingUnknown, RangeOf(t),
          fmt::format("unknown {} '{}'; expected {}{}", context, Text(t), JoinAlternatives(words),
                      hint.empty() ? "" : fmt::format(" (did you mean '{}'?)", hint)));
    }
    return FailExpected(fmt::format("{} ({})", context, JoinAlternatives(words)));
  }
  [[nodiscard]] bool ParseIntegerToken(const Token& t, int* value) {
    auto [ptr, ec] = std::from_chars(text_.data() + t.begin, text_.data() + t.end, *value);
    if (ec != std::errc() || ptr != text_.data() + t.end) {
      return Fail(Diag::BindingIndexRange, RangeOf(t),
                  fmt::format("integer {} is too large", Text(t)));
    }
    return true;
  }
  [[nodiscard]] bool ExpectInteger(std::string_view what, Token* out) {
    if (PeekIs(Tok::Float)) {
      return Fail(Diag::SyntaxExpected, RangeOf(Peek()),
                  fmt::format("expected {} (an integer), found {}", what, Describe(Peek())));
    }
    if (!PeekIs(Tok::Integer)) return FailExpected(fmt::format("{} (an integer)", what));
    return Take(out);
  }
  // ExpectInteger, then its value.
  [[nodiscard]] bool ExpectIntegerValue(std::string_view what, Token* out, int* value) {
    return ExpectInteger(what, out) && ParseIntegerToken(*out, value);
  }

  // ---- program structure ---------------------------------------------------------------

  // <program> ::= <optionSequence> <statementSequence> "END"
  void ParseProgram() {
    bool seen_statement = false;
    for (;;) {
      const Token& t = Peek();
      if (t.kind == Tok::Eof) {
        Report(Diag::SyntaxMissingEnd, {t.begin, t.end},
               "program ends without 'END'; every program must end with the END statement");
        return;
      }
      if (t.kind == Tok::Ident && Is(Text(t), "END")) {
        program_->end = RangeOf(Advance());
        if (!PeekIs(Tok::Eof)) {
          Report(Diag::SyntaxAfterEnd, RangeOf(Peek()),
                 fmt::format("unexpected {} after 'END': END must be the last token of the program "
                             "(comments may follow)",
                             Describe(Peek())));
        }
        return;
      }
      size_t start = pos_;
      bool ok;
      if (t.kind == Tok::Ident && Is(Text(t), "OPTION")) {
        ok = ParseOption(seen_statement);
      } else {
        seen_statement = true;
        ok = ParseStatement();
      }
      if (!ok) {
        if (pos_ == start) Advance();  // always make progress
        Synchronize();
      }
    }
  }

  // Skips to just after the next ';' (or to END / end of program).
  // A statement keyword or opcode that begins a later line than the error also ends the
  // skip, so one missing ';' does not hide the next statement.
  void Synchronize() {
    uint32_t error_line = source_.Locate(last_end_).line;
    while (!PeekIs(Tok::Eof)) {
      if (PeekIs(Tok::Semicolon)) {
        Advance();
        return;
      }
      if (PeekIdent("END") && !PeekIs(Tok::Dot, 1)) return;
      if (StartsStatement(Peek()) && source_.Locate(Peek().begin).line > error_line) return;
      Advance();
    }
  }

  bool StartsStatement(const Token& t) const {
    if (t.kind != Tok::Ident) return false;
    std::string_view s = Text(t);
    if (Is(s, "END") || Is(s, "OPTION") || Is(s, "ATTRIB") || Is(s, "PARAM") || Is(s, "TEMP") ||
        Is(s, "ADDRESS") || Is(s, "OUTPUT") || Is(s, "ALIAS"))
      return true;
    OpcodeWord decoded;
    return DecodeOpcodeWord(s, &decoded);
  }

  // Every statement ends with ';'. A missing one points just after the previous token; when
  // the next token begins a statement on a later line, parsing goes on from there.
  // `what` names the statement ("ATTRIB statement"); `quoted`, when given, is put in
  // quotes before it ("'MOV' instruction"). Messages are built only on failure.
  [[nodiscard]] bool ExpectSemicolon(std::string_view what, std::string_view quoted = {}) {
    if (Accept(Tok::Semicolon)) return true;
    const Token& next = Peek();
    if (next.kind == Tok::Comma) {
      return Fail(Diag::SyntaxExpected, RangeOf(next),
                  fmt::format("expected ';' after the {}{}, found ',': too many operands",
                              Quoted(quoted), what));
    }
    Report(
        Diag::SyntaxMissingSemicolon, {last_end_, last_end_},
        fmt::format("expected ';' after the {}{}, found {}", Quoted(quoted), what, Describe(next)));
    bool later_line = source_.Locate(next.begin).line > source_.Locate(last_end_).line;
    return (later_line && StartsStatement(next)) || next.kind == Tok::Eof;
  }

  // <option> ::= "OPTION" <identifier> ";"
  [[nodiscard]] bool ParseOption(bool after_statement) {
    Token keyword = Advance();
    if (after_statement) {
      Report(Diag::SyntaxOptionPlacement, RangeOf(keyword),
             "OPTION must come before every other statement of the program");
    }
    Token name;
    if (!ExpectIdent("an option name after 'OPTION'", &name)) return false;
    OptionId id;
    if (!LookupOption(Text(name), &id)) {
      std::vector<std::string_view> names;
      for (const OptionInfo& info : AllOptions()) names.push_back(info.spelling);
      std::string hint = ClosestMatch(Text(name), names);
      std::string why;
      if (!hint.empty()) why = fmt::format(" (did you mean '{}'?)", hint);
      Report(Diag::OptionUnknown, RangeOf(name),
             fmt::format("unknown program option '{}'{}", Text(name), why));
    } else {
      program_->options.push_back({id, RangeOf(name)});
    }
    return ExpectSemicolon("OPTION statement");
  }

  // <statement> ::= <instruction> ";" | <namingStatement> ";"
  [[nodiscard]] bool ParseStatement() {
    const Token& t = Peek();
    if (t.kind != Tok::Ident) return FailExpected("an instruction or a declaration");
    std::string_view word = Text(t);
    // <statement> ::= <branchLabel> ":" (NV_vertex_program2, NV_fragment_program2)
    if (PeekIs(Tok::Colon, 1)) return ParseLabel();
    if ((Is(word, "SHORT") || Is(word, "LONG")) && PeekIs(Tok::Ident, 1) &&
        (Is(Text(Peek(1)), "TEMP") || Is(Text(Peek(1)), "OUTPUT"))) {
      return ParseSizedStatement();
    }
    if (Is(word, "ATTRIB")) return ParseAttribStatement();
    if (Is(word, "PARAM")) return ParseParamStatement();
    if (Is(word, "TEMP")) return ParseVarListStatement(VarKind::Temp);
    if (Is(word, "ADDRESS")) {
      if (fp() && !symbols_.Contains("ADDRESS")) {
        return Fail(Diag::SyntaxStatementStage, RangeOf(t),
                    "ADDRESS declarations exist only in vertex programs: fragment programs have "
                    "no address registers");
      }
      if (vp()) return ParseVarListStatement(VarKind::Address);
    }
    if (Is(word, "OUTPUT")) return ParseOutputStatement();
    if (Is(word, "ALIAS")) return ParseAliasStatement();
    return ParseInstruction();
  }

  // <branchLabel> ":"
  [[nodiscard]] bool ParseLabel() {
    Token name = Advance();
    Advance();  // ':'
    const bool allowed = vp() ? program_->NvLevel() >= 1 : program_->NvLevel() >= 2;
    if (!allowed) {
      return Fail(Diag::SyntaxNvConstruct, RangeOf(name),
                  fmt::format("the label '{}:' needs OPTION {}", Text(name),
                              vp() ? "NV_vertex_program2" : "NV_fragment_program2"));
    }
    program_->labels.push_back(
        {std::string(Text(name)), static_cast<int>(program_->instructions.size()), RangeOf(name)});
    return true;
  }

  // <varSize> "TEMP" ... / <varSize> "OUTPUT" ... (NV_fragment_program)
  [[nodiscard]] bool ParseSizedStatement() {
    Token size = Advance();
    if (!(fp() && program_->Nv())) {
      return Fail(Diag::SyntaxNvConstruct, RangeOf(size),
                  fmt::format("'{}' declarations need OPTION NV_fragment_program", Text(size)));
    }
    const size_t first = program_->vars.size();
    const bool temp = Is(Text(Peek()), "TEMP");
    if (!(temp ? ParseVarListStatement(VarKind::Temp) : ParseOutputStatement())) return false;
    for (size_t v = first; v < program_->vars.size(); ++v) {
      program_->vars[v].size = Is(Text(size), "SHORT") ? VarSize::Short : VarSize::Long;
    }
    return true;
  }

  // ---- names ---------------------------------------------------------------------------

  // <establishName> ::= <identifier>; *fresh is false (after reporting) when the name is taken.
  [[nodiscard]] bool ParseEstablishName(Token* name, bool* fresh) {
    if (!ExpectIdent("a variable name", name)) return false;
    std::string_view word = Text(*name);
    if (fp() && program_->NvLevel() >= 2 && Is(word, "A0")) {
      return Fail(Diag::SyntaxReservedName, RangeOf(*name),
                  "'A0' is NV_fragment_program2's predefined address register (the loop index) "
                  "and cannot name a variable");
    }
    if (IsReservedWord(word, kind_) || IsNvReservedWord(word, *program_)) {
      return Fail(Diag::SyntaxReservedName, RangeOf(*name),
                  fmt::format("'{}' is a reserved word and cannot name a variable", word));
    }
    const Symbol* taken = symbols_.Find(word);
    *fresh = taken == nullptr;
    if (!*fresh) {
      Range first = taken->decl;
      compiler::Diagnostic* d = ReportDiagnostic(Diag::DeclRedeclared, RangeOf(*name),
                                                 fmt::format("redeclaration of '{}'", word));
      if (d) d->notes.push_back({&source_, first, fmt::format("'{}' first declared here", word)});
    }
    return true;
  }

  int AddVariable(Variable var, const Token* name) {
    int index = static_cast<int>(program_->vars.size());
    program_->vars.push_back(std::move(var));
    if (name) symbols_.Declare(RangeOf(*name), index, /*replace=*/true);
    return index;
  }
  // AddVariable of a variable with at most one binding, built in place: no temporary
  // Variable to move and destroy (limit tests declare hundreds). `name` is null for an
  // operand's own binding, declared at the binding's text.
  int AddSimpleVariable(VarKind kind, const Token* name, const Binding* binding) {
    int index = static_cast<int>(program_->vars.size());
    Variable& var = program_->vars.emplace_back();
    var.kind = kind;
    if (name) {
      var.name.assign(Text(*name));
      var.decl = RangeOf(*name);
      symbols_.Declare(var.decl, index, /*replace=*/true);
    } else {
      var.decl = binding->range;
    }
    if (binding) var.bindings.push_back(*binding);
    return index;
  }
  void Poison(const Token& name) { symbols_.Declare(RangeOf(name), -1, /*replace=*/false); }

  // Looks up <establishedName>; reports undeclared names (with a suggestion).
  [[nodiscard]] bool ResolveName(const Token& name, int* var) {
    const Symbol* symbol = symbols_.Find(Text(name));
    if (symbol == nullptr) [[unlikely]]
      return ReportUndeclared(name);
    if (symbol->var < 0) return false;  // poisoned: already reported
    *var = symbol->var;
    return true;
  }
  // Out of line: ResolveName stays small. Returns false.
  [[gnu::noinline]] bool ReportUndeclared(const Token& name) {
    std::vector<std::string_view> names = symbols_.Names();
    std::sort(names.begin(), names.end());
    std::string hint = ClosestMatch(Text(name), names);
    return Fail(Diag::DeclUndeclared, RangeOf(name),
                fmt::format("use of undeclared identifier '{}'{}", Text(name),
                            hint.empty() ? "" : fmt::format("; did you mean '{}'?", hint)));
  }

  // ---- declarations ----------------------------------------------------------------------

  // Declares the variable of an ATTRIB or OUTPUT statement (unless its name was taken).
  void AddBoundVariable(const Token& name, bool fresh, VarKind kind, const Binding& binding) {
    if (fresh) AddSimpleVariable(kind, &name, &binding);
  }

  // <ATTRIB_statement> ::= "ATTRIB" <establishName> "=" <vtxAttribBinding>|<fragAttribBinding>
  [[nodiscard]] bool ParseAttribStatement() {
    Advance();
    Token name;
    bool fresh = false;
    if (!ParseEstablishName(&name, &fresh)) return false;
    if (!Expect(Tok::Equals, "'=' after the attribute name")) return false;
    Binding binding;
    if (!ParseAttribStatementBinding(&binding) || !RejectRelativeDeclaration(binding)) {
      if (fresh) Poison(name);
      return false;
    }
    AddBoundVariable(name, fresh, VarKind::Attrib, binding);
    return ExpectSemicolon("ATTRIB statement");
  }
  // An ATTRIB statement's binding; the bindings of the other statements get their own message.
  [[nodiscard]] bool ParseAttribStatementBinding(Binding* binding) {
    const Token& b = Peek();
    if (IsAttribKeyword(b)) return ParseAttribBinding(binding);
    if (b.kind == Tok::Ident && Text(b) == (vp() ? "fragment" : "vertex")) {
      return Fail(Diag::BindingStage, RangeOf(b),
                  fmt::format("'{}.*' bindings exist only in {} programs; {} programs bind {}",
                              Text(b), vp() ? "fragment" : "vertex", vp() ? "vertex" : "fragment",
                              vp() ? "vertex.*" : "fragment.*"));
    }
    if (b.kind == Tok::Ident && (Is(Text(b), "state") || Is(Text(b), "program"))) {
      return Fail(Diag::DeclWrongKind, RangeOf(b),
                  fmt::format("ATTRIB binds {} attributes; '{}' bindings are declared with PARAM",
                              vp() ? "vertex.*" : "fragment.*", Text(b)));
    }
    if (b.kind == Tok::Ident && Is(Text(b), "result")) {
      return Fail(Diag::DeclWrongKind, RangeOf(b),
                  "ATTRIB binds attributes; result bindings are declared with OUTPUT");
    }
    return FailExpected(vp() ? "a vertex attribute binding ('vertex.*')"
                             : "a fragment attribute binding ('fragment.*')");
  }

  // <OUTPUT_statement> ::= "OUTPUT" <establishName> "=" <resultBinding>
  [[nodiscard]] bool ParseOutputStatement() {
    Advance();
    Token name;
    bool fresh = false;
    if (!ParseEstablishName(&name, &fresh)) return false;
    if (!Expect(Tok::Equals, "'=' after the output name")) return false;
    Binding binding;
    bool ok = PeekIdent("result") ? ParseResultBinding(&binding)
                                  : FailExpected("a result binding ('result.*')");
    if (!ok || !RejectRelativeDeclaration(binding)) {
      if (fresh) Poison(name);
      return false;
    }
    AddBoundVariable(name, fresh, VarKind::Output, binding);
    return ExpectSemicolon("OUTPUT statement");
  }

  // The NV grammars let ATTRIB and OUTPUT bind "vertex.attrib[A0.x+n]" too; no compiler
  // emits that (Cg indexes in the instruction), and arbiter takes it only in instructions.
  [[nodiscard]] bool RejectRelativeDeclaration(const Binding& binding) {
    if (!relative_pending_) return true;
    relative_pending_ = false;
    return Fail(Diag::SyntaxNvConstruct, binding.selector,
                "arbiter accepts a relatively addressed attribute or result array only in an "
                "instruction ('MOV r, vertex.attrib[A0.x+1];'), not in a declaration");
  }

  // <TEMP_statement> ::= "TEMP" <varNameList>; <ADDRESS_statement> likewise
  // <varNameList> ::= <establishName> | <establishName> "," <varNameList>
  [[nodiscard]] bool ParseVarListStatement(VarKind kind) {
    Token keyword = Advance();
    do {
      Token name;
      bool fresh = false;
      if (!ParseEstablishName(&name, &fresh)) return false;
      if (fresh) AddSimpleVariable(kind, &name, nullptr);
    } while (Accept(Tok::Comma));
    return ExpectSemicolon("statement", Text(keyword));
  }

  // <ALIAS_statement> ::= "ALIAS" <establishName> "=" <establishedName>
  [[nodiscard]] bool ParseAliasStatement() {
    Advance();
    Token name;
    bool fresh = false;
    if (!ParseEstablishName(&name, &fresh)) return false;
    if (!Expect(Tok::Equals, "'=' after the alias name")) return false;
    Token target;
    if (!ExpectIdent("the name of a declared variable", &target)) return false;
    const Symbol* aliased = symbols_.Find(Text(target));
    if (aliased == nullptr) {
      if (fresh) Poison(name);
      return Fail(Diag::DeclAliasUndeclared, RangeOf(target),
                  fmt::format("ALIAS of undeclared identifier '{}'", Text(target)));
    }
    if (fresh) symbols_.Declare(RangeOf(name), aliased->var, /*replace=*/true);
    return ExpectSemicolon("ALIAS statement");
  }

  // <PARAM_singleStmt>   ::= "PARAM" <establishName> <paramSingleInit>
  // <PARAM_multipleStmt> ::= "PARAM" <establishName> "[" <optArraySize> "]" <paramMultipleInit>
  [[nodiscard]] bool ParseParamStatement() {
    Advance();
    Token name;
    bool fresh = false;
    if (!ParseEstablishName(&name, &fresh)) return false;
    Variable var;
    var.name = std::string(Text(name));
    var.kind = VarKind::Param;
    var.decl = RangeOf(name);
    if (!ParseParamInit(name, &var)) {
      if (fresh) Poison(name);
      return false;
    }
    if (fresh) AddVariable(std::move(var), &name);
    return ExpectSemicolon("PARAM statement");
  }
  // <paramSingleInit> ::= "=" <paramSingleItemDecl>, or an array's size and initialiser.
  [[nodiscard]] bool ParseParamInit(const Token& name, Variable* var) {
    if (!Accept(Tok::LBracket)) {
      Binding b;
      if (!Expect(Tok::Equals, "'=' or '[' after the parameter name")) return false;
      if (!ParseParamSingleItem(/*decl=*/true, &b)) return false;
      var->bindings.push_back(b);
      return true;
    }
    var->is_array = true;
    int declared_size = -1;
    Token size_token{};
    if (!PeekIs(Tok::RBracket)) {
      if (!ExpectIntegerValue("an array size", &size_token, &declared_size)) return false;
      if (declared_size < 1) {
        return Fail(Diag::ParamArraySize, RangeOf(size_token),
                    fmt::format("array '{}' must have at least one element", Text(name)));
      }
    }
    if (!Expect(Tok::RBracket, "']' after the array size")) return false;
    if (!Expect(Tok::Equals, "'=' after the array declaration")) return false;
    // <paramMultipleInit> ::= "=" "{" <paramMultInitList> "}"
    if (!PeekIs(Tok::LBrace)) {
      return FailExpected("'{' and a list of bindings to initialise the array");
    }
    Advance();
    do {
      if (!ParseParamMultipleItem(&var->bindings)) return false;
    } while (Accept(Tok::Comma));
    if (!Expect(Tok::RBrace, "'}' or ',' in the array initialiser")) return false;
    size_t count = var->bindings.size();
    if (declared_size >= 0 && static_cast<size_t>(declared_size) != count) {
      return Fail(Diag::ParamArraySize, RangeOf(size_token),
                  fmt::format("array '{}' is declared with {} element{} but initialised with {} "
                              "binding{}",
                              Text(name), declared_size, declared_size == 1 ? "" : "s", count,
                              count == 1 ? "" : "s"));
    }
    return true;
  }

  // <paramSingleItemDecl> ::= <stateSingleItem> | <programSingleItem> | <paramConstDecl>
  // <paramSingleItemUse>  ::= <stateSingleItem> | <programSingleItem> | <paramConstUse>
  [[nodiscard]] bool ParseParamSingleItem(bool decl, Binding* out) {
    if (PeekIdent("state") || PeekIdent("program")) {
      std::vector<Binding> items;
      bool ok = PeekIdent("state") ? ParseStateItem(&items, /*multiple=*/false)
                                   : ParseProgramItem(&items, /*multiple=*/false);
      if (ok) *out = items.front();
      return ok;
    }
    if (PeekIs(Tok::LBrace)) return ParseConstVector(out);
    if (decl &&
        (PeekIs(Tok::Minus) || PeekIs(Tok::Plus) || PeekIs(Tok::Integer) || PeekIs(Tok::Float))) {
      return ParseConstScalar(/*allow_sign=*/true, out);
    }
    if (!decl && (PeekIs(Tok::Integer) || PeekIs(Tok::Float))) {
      return ParseConstScalar(/*allow_sign=*/false, out);
    }
    return FailExpected("a state binding, a program parameter or a constant");
  }

  // <paramMultipleItem> ::= <stateMultipleItem> | <programMultipleItem> | <paramConstDecl>
  [[nodiscard]] bool ParseParamMultipleItem(std::vector<Binding>* out) {
    if (PeekIdent("state")) return ParseStateItem(out, /*multiple=*/true);
    if (PeekIdent("program")) return ParseProgramItem(out, /*multiple=*/true);
    Binding b;
    bool ok;
    if (PeekIs(Tok::LBrace)) {
      ok = ParseConstVector(&b);
    } else if (PeekIs(Tok::Minus) || PeekIs(Tok::Plus) || PeekIs(Tok::Integer) ||
               PeekIs(Tok::Float)) {
      ok = ParseConstScalar(/*allow_sign=*/true, &b);
    } else {
      return FailExpected("a state binding, a program parameter or a constant");
    }
    if (ok) out->push_back(b);
    return ok;
  }

  // <signedFloatConstant> ::= <optionalSign> <floatConstant>
  [[nodiscard]] bool ParseSignedFloat(bool allow_sign, float* value, Range* range) {
    uint32_t begin = Peek().begin;
    bool negative = false;
    if (PeekIs(Tok::Minus) || PeekIs(Tok::Plus)) {
      Token sign = Advance();
      if (!allow_sign) {
        return Fail(
            Diag::OperandNegatedConstant, RangeOf(sign),
            "an inline scalar constant takes no sign of its own; negate the operand instead");
      }
      negative = Is(Text(sign), "-");
    }
    if (!PeekIs(Tok::Integer) && !PeekIs(Tok::Float)) return FailExpected("a number");
    Token number = Advance();
    float v = ParseFloatText(Text(number));
    if (std::isinf(v) || (v == 0.0f && HasNonZeroDigit(Text(number)))) {
      sink_->Report(Info(Diag::NumberRange), &source_, RangeOf(number),
                    fmt::format("{} is beyond the range of a 32-bit float: it becomes {}",
                                Text(number), std::isinf(v) ? "infinity" : "zero"));
    }
    *range = {begin, number.end};
    *value = negative ? -v : v;
    return true;
  }

  // <paramConstScalarDecl> ::= <signedFloatConstant>; <paramConstScalarUse> ::= <floatConstant>
  [[nodiscard]] bool ParseConstScalar(bool allow_sign, Binding* out) {
    Binding& b = *out;
    b.kind = BindingKind::Constant;
    float v = 0.0f;
    if (!ParseSignedFloat(allow_sign, &v, &b.range)) return false;
    b.value = {v, v, v, v};
    b.selector = b.range;
    return true;
  }

  // <paramConstVector> ::= "{" <signedFloatConstant> ("," <signedFloatConstant>){0,3} "}"
  [[nodiscard]] bool ParseConstVector(Binding* out) {
    Binding& b = *out;
    b.kind = BindingKind::Constant;
    Token open = Advance();
    b.value = {0.0f, 0.0f, 0.0f, 1.0f};
    int count = 0;
    do {
      Range r;
      float v = 0.0f;
      if (!ParseSignedFloat(true, &v, &r)) return false;
      if (count == 4) {
        return Fail(Diag::ParamTooManyComponents, r,
                    "a constant vector has at most four components");
      }
      b.value[static_cast<size_t>(count++)] = v;
    } while (Accept(Tok::Comma));
    Token close;
    if (!Expect(Tok::RBrace, "'}' or ',' in the constant vector", &close)) return false;
    b.range = {open.begin, close.end};
    b.selector = b.range;
    return true;
  }

  // Parses "[" <integer> "]" into *n, the integer token.
  [[nodiscard]] bool ParseBracketIndex(std::string_view what, Token* n) {
    if (!PeekIs(Tok::LBracket)) return FailExpected(fmt::format("'[' and {}", what));
    Advance();
    if (!ExpectInteger(what, n)) return false;
    if (!PeekIs(Tok::RBracket)) return FailExpected(fmt::format("']' after {}", what));
    Advance();
    return true;
  }
  // An optional "[" n "]": sets index/selector/indexed on the binding.
  [[nodiscard]] bool ParseOptionalIndex(Binding* b, std::string_view what) {
    return !PeekIs(Tok::LBracket) || ParseRequiredIndex(b, what);
  }
  [[nodiscard]] bool ParseRequiredIndex(Binding* b, std::string_view what) {
    Token n;
    if (!ParseBracketIndex(what, &n) || !ParseIntegerToken(n, &b->index)) return false;
    b->selector = RangeOf(n);
    b->indexed = true;
    return true;
  }
  // "[" n "]", or with NV_vertex_program3 / NV_fragment_program2 "[" A0.x+n "]": an element
  // of the attribute or result array `array` chosen by an address register. The relative
  // index waits in relative_ for the instruction operand that takes it.
  [[nodiscard]] bool ParseIndexOrRelative(Binding* b, std::string_view what, bool required,
                                          std::string_view array) {
    if (!PeekIs(Tok::LBracket) || !PeekIs(Tok::Ident, 1)) {
      return required ? ParseRequiredIndex(b, what) : ParseOptionalIndex(b, what);
    }
    const Token open = Advance();
    if (program_->NvLevel() < 2) {
      return Fail(
          Diag::OptionRequired, RangeOf(Peek()),
          fmt::format("'{}[{}.x]': relative addressing of attribute and result arrays "
                      "needs OPTION {}",
                      array, Text(Peek()), vp() ? "NV_vertex_program3" : "NV_fragment_program2"));
    }
    if (fp() && array != "fragment.texcoord") {
      return Fail(Diag::OperandRelativeFp, RangeOf(Peek()),
                  "NV_fragment_program2 indexes only fragment.texcoord with its loop index A0.x");
    }
    relative_ = SrcOperand{};
    if (!ParseRelativeIndex(&relative_, /*attribute_array=*/true)) return false;
    if (!Expect(Tok::RBracket, "']' after the relative index")) return false;
    relative_pending_ = true;
    b->indexed = true;
    b->selector = {open.begin, last_end_};
    return true;
  }

  // Consumes "." <word> when the word after the dot is one of `words`.
  bool AcceptDotWord(std::initializer_list<std::string_view> words, std::string_view* got) {
    if (!PeekIs(Tok::Dot) || !PeekIs(Tok::Ident, 1)) return false;
    std::string_view w = Text(Peek(1));
    for (std::string_view candidate : words) {
      if (Is(w, candidate)) {
        Advance();
        Advance();
        *got = w;
        return true;
      }
    }
    return false;
  }
  // True for a word that is meant as a swizzle or mask, valid or not: only component letters,
  // or at most four characters ("xyzq"). Longer words are misspelt binding words.
  static bool LooksLikeSwizzle(std::string_view w) {
    if (w.empty()) return false;
    if (w.size() <= 4) return true;
    for (char c : w) {
      if (std::string_view("xyzwrgba").find(c) == std::string_view::npos) return false;
    }
    return true;
  }
  // After an optional ".word" of a binding: a following ".other" that cannot be a swizzle or
  // mask is a misspelt binding word.
  [[nodiscard]] bool RejectUnknownSuffix(const std::vector<std::string_view>& words,
                                         std::string_view what) {
    if (!PeekIs(Tok::Dot) || !PeekIs(Tok::Ident, 1)) return true;
    const Token& t = Peek(1);
    if (LooksLikeSwizzle(Text(t))) return true;
    std::string hint = ClosestMatch(Text(t), words);
    return Fail(
        Diag::BindingUnknown, RangeOf(t),
        fmt::format("unknown {} '{}'; expected {}{}", what, Text(t), JoinAlternatives(words),
                    hint.empty() ? "" : fmt::format(" (did you mean '{}'?)", hint)));
  }
  [[nodiscard]] bool ExpectDot(std::string_view after) {
    if (!PeekIs(Tok::Dot)) return FailExpected(fmt::format("'.' after '{}'", after));
    Advance();
    return true;
  }

  // ---- bindings ------------------------------------------------------------------------

  bool IsAttribKeyword(const Token& t) const {
    return t.kind == Tok::Ident && Is(Text(t), vp() ? "vertex" : "fragment");
  }

  [[nodiscard]] bool ParseAttribBinding(Binding* out) {
    return vp() ? ParseVertexAttribBinding(out) : ParseFragmentAttribBinding(out);
  }

  // <vtxAttribBinding> ::= "vertex" "." <vtxAttribItem>
  [[nodiscard]] bool ParseVertexAttribBinding(Binding* out) {
    Token start = Advance();
    if (!ExpectDot("vertex")) return false;
    Binding& b = *out;
    b.kind = BindingKind::VertexAttrib;
    Token item;
    if (!ExpectWord({"position", "weight", "normal", "color", "fogcoord", "texcoord", "matrixindex",
                     "attrib"},
                    "vertex attribute", &item)) {
      return false;
    }
    std::string_view w = Text(item);
    b.selector = RangeOf(item);
    b.item = RangeOf(item);
    bool ok = true;
    if (Is(w, "position")) {
      b.vertex_attrib = VertexAttrib::Position;
    } else if (Is(w, "weight")) {
      b.vertex_attrib = VertexAttrib::Weight;
      ok = ParseOptionalIndex(&b, "a weight number");
    } else if (Is(w, "normal")) {
      b.vertex_attrib = VertexAttrib::Normal;
    } else if (Is(w, "color")) {
      std::string_view type;
      b.vertex_attrib = VertexAttrib::Color;
      if (AcceptDotWord({"primary", "secondary"}, &type) && Is(type, "secondary")) {
        b.vertex_attrib = VertexAttrib::SecondaryColor;
      }
      ok = RejectUnknownSuffix({"primary", "secondary"}, "colour type");
    } else if (Is(w, "fogcoord")) {
      b.vertex_attrib = VertexAttrib::FogCoord;
    } else if (Is(w, "texcoord")) {
      b.vertex_attrib = VertexAttrib::TexCoord;
      ok = ParseIndexOrRelative(&b, "a texture coordinate number", false, "vertex.texcoord");
    } else if (Is(w, "matrixindex")) {
      b.vertex_attrib = VertexAttrib::MatrixIndex;
      ok = ParseRequiredIndex(&b, "a matrix index number");
    } else {
      b.vertex_attrib = VertexAttrib::Generic;
      ok = ParseIndexOrRelative(&b, "a generic attribute number", true, "vertex.attrib");
    }
    if (!ok) return false;
    b.range = {start.begin, last_end_};
    return true;
  }

  // <fragAttribBinding> ::= "fragment" "." <fragAttribItem>
  [[nodiscard]] bool ParseFragmentAttribBinding(Binding* out) {
    Token start = Advance();
    if (!ExpectDot("fragment")) return false;
    Binding& b = *out;
    b.kind = BindingKind::FragmentAttrib;
    Token item;
    if (!ExpectWord({"color", "texcoord", "fogcoord", "position", "facing"}, "fragment attribute",
                    &item)) {
      return false;
    }
    std::string_view w = Text(item);
    b.selector = RangeOf(item);
    bool ok = true;
    if (Is(w, "color")) {
      std::string_view type;
      b.fragment_attrib = FragmentAttrib::Color;
      if (AcceptDotWord({"primary", "secondary"}, &type) && Is(type, "secondary")) {
        b.fragment_attrib = FragmentAttrib::SecondaryColor;
      }
      ok = RejectUnknownSuffix({"primary", "secondary"}, "colour type");
    } else if (Is(w, "texcoord")) {
      b.fragment_attrib = FragmentAttrib::TexCoord;
      ok = ParseIndexOrRelative(&b, "a texture coordinate number", false, "fragment.texcoord");
    } else if (Is(w, "fogcoord")) {
      b.fragment_attrib = FragmentAttrib::FogCoord;
    } else if (Is(w, "facing")) {
      // <attribFragBasic> ::= "facing" (NV_fragment_program2)
      if (program_->NvLevel() < 2) {
        return Fail(Diag::OptionRequired, RangeOf(item),
                    "'fragment.facing' needs OPTION NV_fragment_program2");
      }
      b.fragment_attrib = FragmentAttrib::Facing;
    } else {
      b.fragment_attrib = FragmentAttrib::Position;
    }
    if (!ok) return false;
    b.range = {start.begin, last_end_};
    return true;
  }

  // <resultBinding> (ARBvp): "result" "." ("position" | <resultColBinding> | "fogcoord" |
  //                          "pointsize" | "texcoord" <optTexCoordNum>)
  // <resultBinding> (ARBfp): "result" "." ("color" | "depth"); "color" "[" n "]" with
  //                          ARB_draw_buffers
  [[nodiscard]] bool ParseResultBinding(Binding* out) {
    Token start = Advance();
    if (!ExpectDot("result")) return false;
    Binding& b = *out;
    b.kind = BindingKind::Result;
    bool ok = vp() ? ParseVertexResult(&b) : ParseFragmentResult(&b);
    if (!ok) return false;
    b.range = {start.begin, last_end_};
    return true;
  }
  // The vertex-program <resultBinding> after "result" ".".
  [[nodiscard]] bool ParseVertexResult(Binding* b) {
    const Token& t = Peek();
    if (t.kind == Tok::Ident && Is(Text(t), "depth")) {
      return Fail(Diag::BindingStage, RangeOf(t),
                  "'result.depth' is a fragment-program result; vertex programs write "
                  "result.position, result.color, result.fogcoord, result.pointsize or "
                  "result.texcoord");
    }
    Token item;
    if (!ExpectWord({"position", "color", "fogcoord", "pointsize", "texcoord", "clip"},
                    "vertex result", &item)) {
      return false;
    }
    std::string_view w = Text(item);
    b->selector = RangeOf(item);
    if (Is(w, "clip")) {
      // <resultVtxBasic> ::= "clip" "[" <clipPlaneNum> "]" (NV_vertex_program2)
      if (!program_->Nv()) {
        return Fail(Diag::OptionRequired, RangeOf(item),
                    "'result.clip[n]' needs OPTION NV_vertex_program2");
      }
      b->result = ResultReg::ClipDistance;
      return ParseRequiredIndex(b, "a clip plane number");
    }
    if (Is(w, "position")) {
      b->result = ResultReg::Position;
    } else if (Is(w, "color")) {
      // <resultColBinding> ::= "color" <optFaceType> <optColorType>
      b->result = ResultReg::Color;
      std::string_view word;
      if (AcceptDotWord({"front", "back"}, &word))
        b->face = Is(word, "back") ? Face::Back : Face::Front;
      if (AcceptDotWord({"primary", "secondary"}, &word)) b->secondary = Is(word, "secondary");
      return RejectUnknownSuffix({"front", "back", "primary", "secondary"}, "colour result");
    } else if (Is(w, "fogcoord")) {
      b->result = ResultReg::FogCoord;
    } else if (Is(w, "pointsize")) {
      b->result = ResultReg::PointSize;
    } else {
      b->result = ResultReg::TexCoord;
      return ParseIndexOrRelative(b, "a texture coordinate number", false, "result.texcoord");
    }
    return true;
  }
  // The fragment-program <resultBinding> after "result" ".".
  [[nodiscard]] bool ParseFragmentResult(Binding* b) {
    const Token& t = Peek();
    if (t.kind == Tok::Ident && (Is(Text(t), "position") || Is(Text(t), "fogcoord") ||
                                 Is(Text(t), "pointsize") || Is(Text(t), "texcoord"))) {
      return Fail(Diag::BindingStage, RangeOf(t),
                  fmt::format("'result.{}' is a vertex-program result; fragment programs write "
                              "result.color and result.depth",
                              Text(t)));
    }
    Token item;
    if (!ExpectWord({"color", "depth"}, "fragment result", &item)) return false;
    b->selector = RangeOf(item);
    if (!Is(Text(item), "color")) {
      b->result = ResultReg::FragDepth;
      return true;
    }
    b->result = ResultReg::FragColor;
    if (!ParseOptionalIndex(b, "a draw buffer number")) return false;
    if (PeekIs(Tok::Dot) && PeekIs(Tok::Ident, 1)) {
      std::string_view next = Text(Peek(1));
      if (Is(next, "front") || Is(next, "back") || Is(next, "primary") || Is(next, "secondary")) {
        return Fail(Diag::BindingStage, RangeOf(Peek(1)),
                    fmt::format("'result.color.{}' exists only in vertex programs; a fragment "
                                "program writes result.color",
                                next));
      }
    }
    return true;
  }

  // <progEnvParam(s)> / <progLocalParam(s)>:
  //   "program" "." ("env" | "local") "[" n ( ".." m )? "]"
  [[nodiscard]] bool ParseProgramItem(std::vector<Binding>* out, bool multiple) {
    Token start = Advance();
    if (!ExpectDot("program")) return false;
    Token which;
    if (!ExpectWord({"env", "local"}, "program parameter", &which)) return false;
    if (!Expect(Tok::LBracket, "'[' and a parameter number")) return false;
    Token first;
    int lo = 0;
    if (!ExpectIntegerValue("a parameter number", &first, &lo)) return false;
    int hi = lo;
    Token last = first;
    bool range = false;
    if (Accept(Tok::DotDot)) {
      if (!ExpectIntegerValue("the last parameter number of the range", &last, &hi)) return false;
      range = true;
    }
    Token close;
    if (!Expect(Tok::RBracket, range ? "']'" : "']' or '..'", &close)) return false;
    if (range && !multiple) {
      return Fail(Diag::ParamArrayItem, {start.begin, close.end},
                  fmt::format("'program.{}[{}..{}]' binds several vectors; it can only "
                              "initialise a PARAM array",
                              Text(which), lo, hi));
    }
    if (hi < lo) {
      return Fail(Diag::BindingRowRange, RangeOf(last),
                  fmt::format("parameter range [{}..{}] ends before it starts", lo, hi));
    }
    // At most a few thousand at once: a range far beyond every limit is still pushed one by one.
    out->reserve(out->size() + std::min<size_t>(static_cast<size_t>(hi - lo) + 1, 4096));
    for (int i = lo; i <= hi; ++i) {
      Binding b;
      b.kind = Is(Text(which), "env") ? BindingKind::ProgramEnv : BindingKind::ProgramLocal;
      b.index = i;
      b.indexed = true;
      // A range is checked at its last number, a single parameter at its number.
      b.selector = (i == hi) ? RangeOf(last) : RangeOf(first);
      b.range = {start.begin, close.end};
      out->push_back(b);
    }
    return true;
  }

  // <stateSingleItem> / <stateMultipleItem> ::= "state" "." ...
  [[nodiscard]] bool ParseStateItem(std::vector<Binding>* out, bool multiple) {
    Token start = Advance();
    if (!ExpectDot("state")) return false;
    const Token& t = Peek();
    if (t.kind == Tok::Ident) {
      const glstate::StateGroupInfo* group = glstate::FindStateGroup(Text(t));
      if (group && !glstate::GroupInStage(*group, vp())) {
        return Fail(Diag::BindingStage, RangeOf(t),
                    fmt::format("'state.{}' is available only in {} programs", group->word,
                                vp() ? "fragment" : "vertex"));
      }
    }
    // The group words of each program kind, built once: every state binding looks them up.
    static const std::array<std::vector<std::string_view>, 2> kGroups = [] {
      std::array<std::vector<std::string_view>, 2> words;
      for (const glstate::StateGroupInfo& group : glstate::kStateGroups) {
        for (int vertex = 0; vertex < 2; ++vertex) {
          if (glstate::GroupInStage(group, vertex == 1)) words[vertex].push_back(group.word);
        }
      }
      return words;
    }();
    Token word;
    if (!ExpectWordSlow(kGroups[vp() ? 1 : 0], "state binding", &word)) return false;
    const glstate::StateGroupInfo& group = *glstate::FindStateGroup(Text(word));
    Binding b;
    b.kind = BindingKind::State;
    b.selector = RangeOf(word);
    if (group.word == "matrix") return ParseMatrixItem(start, b, out, multiple);
    if (!ParseStateProperty(group, &b)) return false;
    b.range = {start.begin, last_end_};
    out->push_back(b);
    return true;
  }

  // The rest of a state binding after its group word, as state_items.def lists it: the
  // selector, the face, the property words and the texgen coordinate.
  [[nodiscard]] bool ParseStateProperty(const glstate::StateGroupInfo& group, Binding* b) {
    if (group.selector != glstate::StateSelector::None) {
      const glstate::StateSelectorInfo& selector = glstate::GetStateSelectorInfo(group.selector);
      const std::string what = fmt::format("a {} number", selector.noun);
      if (!(selector.required ? ParseRequiredIndex(b, what) : ParseOptionalIndex(b, what))) {
        return false;
      }
    }
    std::string_view after = b->indexed ? "]" : group.word;
    std::string_view face;
    if (group.faced && AcceptDotWord({"front", "back"}, &face)) {
      b->face = Is(face, "back") ? Face::Back : Face::Front;
      after = face;
    }
    // The items of the group this spelling can still name, and their first property words.
    auto first_word = [](std::string_view property) {
      return property.substr(0, property.find('.'));
    };
    std::vector<const glstate::StateItemInfo*> items;
    std::vector<std::string_view> words;
    for (const glstate::StateItemInfo& info : glstate::kStateItems) {
      if (info.group != group.word || (!face.empty() && !info.faced)) continue;
      items.push_back(&info);
      words.push_back(first_word(info.property));
    }
    Token prop;
    if (!ExpectDot(after) || !ExpectWordSlow(words, group.noun, &prop)) return false;
    const glstate::StateItemInfo& item =
        **std::find_if(items.begin(), items.end(), [&](const glstate::StateItemInfo* info) {
          return first_word(info->property) == Text(prop);
        });
    b->state = item.item;
    // A property of several words ("spot.direction").
    std::string_view previous = Text(prop);
    for (std::string_view rest = item.property.substr(previous.size()); !rest.empty();) {
      rest.remove_prefix(1);  // the '.'
      const std::string_view next = first_word(rest);
      if (!ExpectDot(previous) || !ExpectWord({next}, fmt::format("{} property", previous))) {
        return false;
      }
      previous = next;
      rest.remove_prefix(next.size());
    }
    if (group.coord) {
      Token coord;
      if (!ExpectDot(previous) || !ExpectWord({"s", "t", "r", "q"}, "texgen coordinate", &coord)) {
        return false;
      }
      b->coord = static_cast<uint8_t>(std::string_view("strq").find(Text(coord)));
    }
    return true;
  }

  // <stateMatrixItem> ::= "matrix" "." <stateMatrixName> <stateOptMatModifier>
  // followed by ".row[n]" (single) or an optional ".row[a..b]" (multiple).
  [[nodiscard]] bool ParseMatrixItem(const Token& start, Binding b, std::vector<Binding>* out,
                                     bool multiple) {
    b.state = StateItem::MatrixRow;
    if (!ExpectDot("matrix")) return false;
    std::vector<std::string_view> names;
    for (const glstate::StateMatrixInfo& info : glstate::kStateMatrices) names.push_back(info.word);
    Token name;
    if (!ExpectWordSlow(names, "matrix name", &name)) return false;
    const glstate::StateMatrixInfo& matrix = *std::find_if(
        std::begin(glstate::kStateMatrices), std::end(glstate::kStateMatrices),
        [&](const glstate::StateMatrixInfo& info) { return info.word == Text(name); });
    b.selector = RangeOf(name);
    b.item = RangeOf(name);
    b.matrix = matrix.matrix;
    const std::string what = fmt::format("a {} number", matrix.noun);
    const bool ok = matrix.index == glstate::MatrixIndex::Required   ? ParseRequiredIndex(&b, what)
                    : matrix.index == glstate::MatrixIndex::Optional ? ParseOptionalIndex(&b, what)
                                                                     : true;
    if (!ok) return false;
    std::string_view word;
    if (AcceptDotWord({"inverse", "transpose", "invtrans"}, &word)) {
      b.modifier = Is(word, "inverse")     ? MatrixModifier::Inverse
                   : Is(word, "transpose") ? MatrixModifier::Transpose
                                           : MatrixModifier::InvTrans;
    }
    if (PeekIs(Tok::Dot) && PeekIs(Tok::Ident, 1) && !Is(Text(Peek(1)), "row") &&
        !LooksLikeSwizzle(Text(Peek(1)))) {
      const Token& bad = Peek(1);
      return Fail(Diag::BindingUnknown, RangeOf(bad),
                  fmt::format("unknown matrix modifier '{}'; expected 'inverse', 'transpose', "
                              "'invtrans' or 'row'",
                              Text(bad)));
    }
    int lo = 0;
    int hi = 3;
    Range lo_range = RangeOf(name);
    Range hi_range = RangeOf(name);
    bool has_rows = false;
    bool row_range = false;
    if (AcceptDotWord({"row"}, &word)) {
      has_rows = true;
      if (!Expect(Tok::LBracket, "'[' and a row number")) return false;
      Token first;
      if (!ExpectIntegerValue("a row number", &first, &lo)) return false;
      hi = lo;
      lo_range = hi_range = RangeOf(first);
      if (Accept(Tok::DotDot)) {
        row_range = true;
        Token last;
        if (!ExpectIntegerValue("the last row number", &last, &hi)) return false;
        hi_range = RangeOf(last);
      }
      if (!Expect(Tok::RBracket, row_range ? "']'" : "']' or '..'")) return false;
      // <stateMatrixRowNum> ::= <integer> from 0 to 3
      if (lo > 3) {
        return Fail(Diag::BindingIndexRange, lo_range,
                    fmt::format("matrix row {} does not exist; rows are numbered 0 to 3", lo));
      }
      if (hi > 3) {
        return Fail(Diag::BindingIndexRange, hi_range,
                    fmt::format("matrix row {} does not exist; rows are numbered 0 to 3", hi));
      }
      if (hi < lo) {
        return Fail(Diag::BindingRowRange, hi_range,
                    fmt::format("row range [{}..{}] ends before it starts", lo, hi));
      }
    }
    Range whole = {start.begin, last_end_};
    if (!multiple && (!has_rows || row_range)) {
      return Fail(Diag::BindingMatrixNotSingle, RangeOf(start),
                  fmt::format("'{}' binds {} rows where one vector is expected; select one with "
                              "'.row[n]' or bind the rows to a PARAM array",
                              std::string_view(text_).substr(whole.begin, whole.end - whole.begin),
                              hi - lo + 1));
    }
    for (int r = lo; r <= hi; ++r) {
      Binding row = b;
      row.row = static_cast<uint8_t>(r);
      row.row_sel = r == hi ? hi_range : lo_range;
      row.range = whole;
      out->push_back(row);
    }
    return true;
  }

  // ---- instructions --------------------------------------------------------------------

  [[nodiscard]] bool ParseInstruction() {
    Token op_token = Advance();
    std::string_view word = Text(op_token);
    Instruction inst;
    inst.opcode_range = RangeOf(op_token);
    OpcodeWord decoded;
    if (!DecodeOpcodeWord(word, &decoded)) return ReportUnknownStatement(op_token);
    inst.op = decoded.op;
    inst.saturate = decoded.saturate;
    inst.signed_saturate = decoded.signed_saturate;
    inst.precision = decoded.precision;
    inst.cc_update = decoded.cc;
    const OpcodeInfo& info = GetOpcodeInfo(inst.op);
    if (inst.saturate && inst.op == Opcode::KIL) {
      return Fail(Diag::SyntaxUnknownOpcode, RangeOf(op_token),
                  "unknown instruction 'KIL_SAT': KIL writes no register, so it has no _SAT form");
    }
    if (!program_->HasOpcode(inst.op)) return ReportOpcodeUnavailable(op_token, info);
    if (!CheckModifiers(op_token, info, inst)) return false;
    if (!ParseOperands(info, &inst)) return false;
    inst.range = {op_token.begin, last_end_};
    program_->instructions.push_back(inst);
    return ExpectSemicolon("instruction", info.name);
  }

  // An opcode this program does not have: of the other kind, or of an NV option it lacks.
  [[nodiscard]] bool ReportOpcodeUnavailable(const Token& op_token, const OpcodeInfo& info) {
    const OpLevel here = OpcodeLevel(info.op, kind_);
    if (here == OpLevel::No) {
      const OpLevel there =
          OpcodeLevel(info.op, vp() ? ProgramKind::Fragment : ProgramKind::Vertex);
      const std::string_view other = vp() ? "fragment" : "vertex";
      return Fail(Diag::SyntaxOpcodeStage, RangeOf(op_token),
                  there == OpLevel::Arb
                      ? fmt::format("'{}' is a {}-program instruction; it is not available in {} "
                                    "programs",
                                    info.name, other, vp() ? "vertex" : "fragment")
                      : fmt::format("'{}' is a {}-program instruction of OPTION {}; it is not "
                                    "available in {} programs",
                                    info.name, other, NvOptionName(!vp(), there),
                                    vp() ? "vertex" : "fragment"));
    }
    const OpLevel there = OpcodeLevel(info.op, vp() ? ProgramKind::Fragment : ProgramKind::Vertex);
    if (there == OpLevel::Arb && !program_->Nv()) {
      return Fail(Diag::SyntaxOpcodeStage, RangeOf(op_token),
                  fmt::format("'{}' is a {}-program instruction; {} programs have it only with "
                              "OPTION {}",
                              info.name, vp() ? "fragment" : "vertex", vp() ? "vertex" : "fragment",
                              NvOptionName(vp(), here)));
    }
    return Fail(Diag::OptionRequired, RangeOf(op_token),
                fmt::format("'{}' needs OPTION {}", info.name, NvOptionName(vp(), here)));
  }

  // The suffixes of an opcode against its row of table X.5 and the program's options.
  [[nodiscard]] bool CheckModifiers(const Token& op_token, const OpcodeInfo& info,
                                    const Instruction& inst) {
    const int level = program_->NvLevel();
    const std::string_view mods = OpcodeModifiers(info, kind_, level);
    auto has = [&](char m) { return mods.find(m) != std::string_view::npos; };
    auto fail = [&](std::string_view what, std::string_view need) {
      return Fail(Diag::SyntaxModifier, RangeOf(op_token),
                  fmt::format("'{}': {} {}", Text(op_token), what, need));
    };
    if ((inst.saturate || inst.signed_saturate) && !has('S')) {
      if (vp() && level < 2 && !info.vp_mods.empty() && inst.saturate) {
        return Fail(Diag::SyntaxSaturateVp, RangeOf(op_token),
                    fmt::format("'{}': the _SAT suffix exists only in fragment programs (and in "
                                "vertex programs with OPTION NV_vertex_program3); clamp with MIN "
                                "and MAX",
                                Text(op_token)));
      }
      return fail(inst.signed_saturate ? "_SSAT" : "_SAT",
                  fmt::format("is not a form of {} here", info.name));
    }
    if (inst.signed_saturate && level < 2) {
      return fail("_SSAT", "needs OPTION NV_fragment_program2");
    }
    if (inst.cc_update >= 0 && !has('C')) {
      return fail("the condition code update suffix",
                  level == 0 ? fmt::format("needs OPTION {}", NvOptionName(vp(), OpLevel::Nv))
                             : fmt::format("is not a form of {}", info.name));
    }
    if (inst.cc_update == 1 && !(vp() && level >= 2)) {
      return fail("condition code register 1", "needs OPTION NV_vertex_program3");
    }
    if (inst.precision != Precision::Default) {
      const char letter = "?RHX"[static_cast<int>(inst.precision)];
      if (!has(letter)) {
        return fail(fmt::format("the precision suffix '{}'", letter),
                    level == 0 || vp() ? std::string("needs OPTION NV_fragment_program")
                                       : fmt::format("is not a form of {}", info.name));
      }
    }
    return true;
  }

  // The operands of an instruction, as its opcode's signature lists them.
  [[nodiscard]] bool ParseOperands(const OpcodeInfo& info, Instruction* inst) {
    switch (info.signature) {
      case OpSignature::Vector:
      case OpSignature::Binary:
      case OpSignature::Ternary:
      case OpSignature::Scalar:
      case OpSignature::BinSc: {
        bool scalar = info.signature == OpSignature::Scalar || info.signature == OpSignature::BinSc;
        if (!ParseMaskedDstReg(&inst->dst)) return false;
        int n = SourceCount(info.signature);
        for (int i = 0; i < n; ++i) {
          if (!Expect(Tok::Comma, "',' and a source operand") ||
              !ParseSwizzleSrcReg(scalar, scalar ? info.name : std::string_view(),
                                  &inst->src[static_cast<size_t>(i)])) {
            return false;
          }
        }
        inst->src_count = static_cast<uint8_t>(n);
        return true;
      }
      case OpSignature::Swz:
        inst->src_count = 1;
        return ParseMaskedDstReg(&inst->dst) && Expect(Tok::Comma, "',' and a source operand") &&
               ParseSwzSource(&inst->src[0]);
      case OpSignature::Arl:
        // <ARLop_src> ::= <instOperandV> under NV_vertex_program2: A0.xy = floor(v.xy).
        inst->src_count = 1;
        return ParseMaskedAddrReg(&inst->dst) && Expect(Tok::Comma, "',' and a source operand") &&
               ParseSwizzleSrcReg(!program_->Nv(), info.name, &inst->src[0]);
      case OpSignature::Sample:
        inst->src_count = 1;
        return ParseMaskedDstReg(&inst->dst) &&
               Expect(Tok::Comma, "',' and the texture coordinate") &&
               ParseSwizzleSrcReg(false, {}, &inst->src[0]) &&
               Expect(Tok::Comma, "',' and a texture unit ('texture[n]')") &&
               ParseTexImageUnit(inst) && Expect(Tok::Comma, "',' and a texture target") &&
               ParseTexTarget(inst);
      case OpSignature::VecSca:
        inst->src_count = 2;
        return ParseMaskedDstReg(&inst->dst) && Expect(Tok::Comma, "',' and a source operand") &&
               ParseSwizzleSrcReg(false, {}, &inst->src[0]) &&
               Expect(Tok::Comma, "',' and a scalar operand") &&
               ParseSwizzleSrcReg(true, info.name, &inst->src[1]);
      case OpSignature::Ara:
        inst->src_count = 1;
        return ParseMaskedAddrReg(&inst->dst, info.name) &&
               Expect(Tok::Comma, "',' and an address register") &&
               ParseAddressOperand(info.name, &inst->src[0]);
      case OpSignature::Arr:
        inst->src_count = 1;
        return ParseMaskedAddrReg(&inst->dst, info.name) &&
               Expect(Tok::Comma, "',' and a source operand") &&
               ParseSwizzleSrcReg(false, {}, &inst->src[0]);
      case OpSignature::PushA:
        inst->src_count = 1;
        return ParseAddressOperand(info.name, &inst->src[0]);
      case OpSignature::PopA:
        if (!ParseMaskedAddrReg(&inst->dst, info.name)) return false;
        // NV_vertex_program3 2.14.5.43: "a program will fail to load if it includes a component
        // write mask other than ".xyzw" or a condition code write mask test other than "TR"".
        if (inst->dst.mask != 0xF || (inst->dst.cc.present && inst->dst.cc.rule != CcRule::TR)) {
          return Fail(Diag::OperandBadMask, inst->dst.range,
                      "POPA writes the whole address register: no write mask but '.xyzw' and no "
                      "condition code test but TR");
        }
        return true;
      case OpSignature::TexD:
        inst->src_count = 3;
        if (!ParseMaskedDstReg(&inst->dst)) return false;
        for (size_t i = 0; i < 3; ++i) {
          if (!Expect(Tok::Comma, "',' and a source operand") ||
              !ParseSwizzleSrcReg(false, {}, &inst->src[i])) {
            return false;
          }
        }
        return Expect(Tok::Comma, "',' and a texture unit ('texture[n]')") &&
               ParseTexImageUnit(inst) && Expect(Tok::Comma, "',' and a texture target") &&
               ParseTexTarget(inst);
      case OpSignature::Branch: {
        Token label;
        if (!ExpectIdent("a label", &label)) return false;
        inst->label = std::string(Text(label));
        inst->label_range = RangeOf(label);
        return ParseOptionalCcMask(&inst->cond);
      }
      case OpSignature::FlowCc:
        return ParseOptionalCcMask(&inst->cond);
      case OpSignature::If:
        return ParseCcTest(&inst->cond);
      case OpSignature::Loop:
        inst->src_count = 1;
        return ParseSwizzleSrcReg(false, {}, &inst->src[0]);
      case OpSignature::EndFlow:
        return true;
      case OpSignature::Kil:
        // <killCond> ::= <ccTest> under NV_fragment_program.
        if (program_->Nv() && PeekIs(Tok::Ident) && IsCcRule(Text(Peek())) &&
            !symbols_.Contains(Text(Peek()))) {
          return ParseCcTest(&inst->cond);
        }
        inst->src_count = 1;
        if (!ParseSwizzleSrcReg(false, {}, &inst->src[0])) return false;
        if (PeekIs(Tok::Comma)) {
          return Fail(Diag::SyntaxExpected, RangeOf(Peek()),
                      "KIL takes exactly one source operand and no destination");
        }
        return true;
    }
    return true;
  }

  // <ccTest> ::= <ccMaskRule> <swizzleSuffix>; the rule may name register 0 or 1 ("GT1") under
  // NV_vertex_program3.
  [[nodiscard]] bool ParseCcTest(CcTest* cc) {
    Token rule;
    if (!ExpectIdent("a condition code test (EQ, GE, GT, LE, LT, NE, TR or FL)", &rule)) {
      return false;
    }
    std::string_view w = Text(rule);
    if (!IsCcRule(w)) {
      return Fail(Diag::SyntaxExpected, RangeOf(rule),
                  fmt::format("'{}' is not a condition code test; use EQ, GE, GT, LE, LT, NE, TR "
                              "or FL",
                              w));
    }
    cc->present = true;
    cc->rule = CcRuleOf(w.substr(0, 2));
    cc->reg = w.size() == 3 ? static_cast<uint8_t>(w[2] - '0') : 0;
    if (w.size() == 3 && !(vp() && program_->NvLevel() >= 2)) {
      return Fail(
          Diag::SyntaxModifier, RangeOf(rule),
          fmt::format("'{}': condition code register {} needs OPTION NV_vertex_program3", w, w[2]));
    }
    cc->range = RangeOf(rule);
    if (PeekIs(Tok::Dot)) {
      Advance();
      Token swz;
      SrcOperand tmp;
      if (!ExpectIdent("a swizzle", &swz) || !ParseSwizzle(swz, false, {}, &tmp)) return false;
      cc->swizzle = tmp.swizzle;
      cc->range.end = last_end_;
    }
    return true;
  }

  // <optBranchCond> / the conditional write mask: "(" <ccTest> ")" or nothing.
  [[nodiscard]] bool ParseOptionalCcMask(CcTest* cc) {
    if (!PeekIs(Tok::LParen)) return true;
    Token open = Advance();
    if (!program_->Nv()) {
      return Fail(
          Diag::SyntaxNvConstruct, RangeOf(open),
          fmt::format("a condition code mask needs OPTION {}", NvOptionName(vp(), OpLevel::Nv)));
    }
    return ParseCcTest(cc) && Expect(Tok::RParen, "')' after the condition code test");
  }

  // An inline scalar constant ("3.5"): one value, whatever the swizzle.
  bool IsInlineScalar(const SrcOperand& src) const {
    const Variable& v = program_->vars[static_cast<size_t>(src.var)];
    if (!v.name.empty() || v.kind != VarKind::Param || v.bindings.size() != 1) return false;
    const Binding& b = v.bindings[0];
    return b.kind == BindingKind::Constant && b.value[0] == b.value[1] &&
           b.value[0] == b.value[2] && b.value[0] == b.value[3];
  }

  // <instOperandAddrVNS> ::= <addrVarName>: a whole address register (ARA, PUSHA).
  [[nodiscard]] bool ParseAddressOperand(std::string_view opname, SrcOperand* src) {
    Token name;
    if (!ExpectIdent("an address register", &name) || !ResolveName(name, &src->var)) return false;
    if (program_->vars[static_cast<size_t>(src->var)].kind != VarKind::Address) {
      return Fail(Diag::DeclWrongKind, RangeOf(name),
                  fmt::format("{} reads an address register, but '{}' is a {}", opname, Text(name),
                              KindName(program_->vars[static_cast<size_t>(src->var)].kind)));
    }
    src->range = RangeOf(name);
    return true;
  }

  // Reports a statement that begins with no known instruction or keyword; returns false.
  [[nodiscard]] bool ReportUnknownStatement(const Token& t) {
    std::string_view word = Text(t);
    std::vector<std::string_view> names;
    for (const OpcodeInfo& info : AllOpcodes()) {
      if (OpcodeInStage(info.op, kind_)) names.push_back(info.name);
    }
    for (std::string_view k : {"ATTRIB", "PARAM", "TEMP", "OUTPUT", "ALIAS", "OPTION", "END"}) {
      names.push_back(k);
    }
    if (vp()) names.push_back("ADDRESS");
    if (symbols_.Contains(word)) {
      return Fail(
          Diag::SyntaxUnknownOpcode, RangeOf(t),
          fmt::format("expected an instruction or a declaration, found the variable '{}'", word));
    }
    std::string hint = ClosestMatch(word, names);
    std::string note;
    if (!hint.empty()) {
      note = fmt::format("; did you mean '{}'?", hint);
      if (hint.size() == word.size() && hint != word) {
        bool same_letters = true;
        for (size_t i = 0; i < word.size(); ++i) {
          if (std::toupper(static_cast<unsigned char>(word[i])) != hint[i]) same_letters = false;
        }
        if (same_letters)
          note = fmt::format("; did you mean '{}'? (instructions are upper case)", hint);
      }
    }
    return Fail(Diag::SyntaxUnknownOpcode, RangeOf(t),
                fmt::format("unknown instruction '{}'{}", word, note));
  }

  // <maskedDstReg> ::= <dstReg> <optionalMask>
  // <dstReg> ::= <temporaryReg> | <vertexResultReg> / <fragmentResultReg>
  [[nodiscard]] bool ParseMaskedDstReg(DstOperand* out) {
    DstOperand& dst = *out;
    const Token& t = Peek();
    uint32_t begin = t.begin;
    if (PeekIdent("result")) {
      Binding b;
      if (!ParseResultBinding(&b)) return false;
      if (relative_pending_) {
        relative_pending_ = false;
        dst.var = AddRelativeArray(VarKind::Output, b);
        dst.relative = true;
        dst.address_var = relative_.address_var;
        dst.address_component = relative_.address_component;
        dst.index = relative_.index;
      } else {
        dst.var = AddImplicit(VarKind::Output, b);
      }
    } else if (t.kind == Tok::Ident && IsBindingStart(t)) {
      return Fail(Diag::OperandDstReadOnly, RangeOf(t),
                  fmt::format("cannot write to a '{}' binding: destinations are temporaries and "
                              "result registers",
                              Text(t)));
    } else if (t.kind == Tok::Ident) {
      Token name = Advance();
      int var = 0;
      if (!ResolveName(name, &var)) return false;
      VarKind k = program_->vars[static_cast<size_t>(var)].kind;
      if (k == VarKind::Attrib || k == VarKind::Param) {
        return Fail(Diag::OperandDstReadOnly, RangeOf(name),
                    fmt::format("cannot write to {} '{}': {} are read-only", KindName(k),
                                Text(name), k == VarKind::Attrib ? "attributes" : "parameters"));
      }
      if (k == VarKind::Address) {
        return Fail(Diag::DeclWrongKind, RangeOf(name),
                    fmt::format("address register '{}' can only be written by ARL", Text(name)));
      }
      if (PeekIs(Tok::LBracket)) {
        return Fail(Diag::OperandNotArray, RangeOf(Peek()),
                    fmt::format("'{}' is not an array and cannot be indexed", Text(name)));
      }
      dst.var = var;
    } else {
      return FailExpected("a destination register");
    }
    dst.range = {begin, last_end_};
    // <optionalMask>
    if (PeekIs(Tok::Dot)) {
      Advance();
      Token mask;
      if (!ExpectIdent("a write mask", &mask) || !ParseMask(mask, &dst.mask)) return false;
    }
    // <instResultCC> ::= <instResultBase> <ccMask> (NV options)
    return ParseOptionalCcMask(&dst.cc);
  }

  static std::string_view KindName(VarKind k) {
    switch (k) {
      case VarKind::Attrib:
        return "attribute";
      case VarKind::Param:
        return "parameter";
      case VarKind::Temp:
        return "temporary";
      case VarKind::Address:
        return "address register";
      case VarKind::Output:
        return "output";
    }
    return "variable";
  }

  // Component letter -> index and set (1 xyzw, 2 rgba); 0 if not a component.
  static int ComponentOf(char c, int* set) {
    switch (c) {
      case 'x':
        *set = 1;
        return 0;
      case 'y':
        *set = 1;
        return 1;
      case 'z':
        *set = 1;
        return 2;
      case 'w':
        *set = 1;
        return 3;
      case 'r':
        *set = 2;
        return 0;
      case 'g':
        *set = 2;
        return 1;
      case 'b':
        *set = 2;
        return 2;
      case 'a':
        *set = 2;
        return 3;
      default:
        *set = 0;
        return -1;
    }
  }

  // Checks the component set of a swizzle or mask (xyzw vs rgba, rgba only in fp).
  [[nodiscard]] bool CheckComponentSets(const Token& t, int sets, std::string_view what) {
    if (sets == 3) {
      return Fail(Diag::OperandSwizzleMix, RangeOf(t),
                  fmt::format("{} '{}' mixes xyzw and rgba component names", what, Text(t)));
    }
    if (sets == 2 && vp()) {
      return Fail(Diag::OperandRgbaVp, RangeOf(t),
                  fmt::format("{} '{}' uses rgba component names, which only fragment programs "
                              "accept; use xyzw",
                              what, Text(t)));
    }
    return true;
  }

  // <optionalMask>: components in order x, y, z, w, each at most once.
  [[nodiscard]] bool ParseMask(const Token& t, uint8_t* mask_out) {
    std::string_view s = Text(t);
    int sets = 0;
    uint8_t mask = 0;
    int last = -1;
    bool ordered = true;
    for (char c : s) {
      int set = 0;
      int comp = ComponentOf(c, &set);
      if (comp < 0 || s.size() > 4) {
        return Fail(Diag::OperandBadMask, RangeOf(t),
                    fmt::format("'{}' is not a write mask; a mask lists components of {} in order",
                                s, fp() ? "xyzw or rgba" : "xyzw"));
      }
      sets |= set;
      if (comp <= last) ordered = false;
      last = comp;
      mask = static_cast<uint8_t>(mask | (1u << comp));
    }
    if (!CheckComponentSets(t, sets, "write mask")) return false;
    if (!ordered) {
      return Fail(Diag::OperandBadMask, RangeOf(t),
                  fmt::format("write mask '{}' must list each component at most once, in the "
                              "order {}",
                              s, sets == 2 ? "r, g, b, a" : "x, y, z, w"));
    }
    *mask_out = mask;
    return true;
  }

  // <maskedAddrReg> ::= <addrReg> <addrWriteMask>; <addrWriteMask> ::= "." "x"
  [[nodiscard]] bool ParseMaskedAddrReg(DstOperand* out, std::string_view opname = "ARL") {
    DstOperand& dst = *out;
    Token name;
    int var = 0;
    if (!ExpectIdent("an address register", &name) || !ResolveName(name, &var)) return false;
    if (program_->vars[static_cast<size_t>(var)].kind != VarKind::Address) {
      return Fail(Diag::DeclWrongKind, RangeOf(name),
                  fmt::format("{} writes an address register, but '{}' is a {}", opname, Text(name),
                              KindName(program_->vars[static_cast<size_t>(var)].kind)));
    }
    dst.var = var;
    dst.range = RangeOf(name);
    // NV_vertex_program2: <addrUseW> ::= <addrVarName> <optAddrWriteMask>, any components.
    if (program_->Nv()) {
      if (PeekIs(Tok::Dot)) {
        Advance();
        Token mask;
        if (!ExpectIdent("a write mask", &mask) || !ParseMask(mask, &dst.mask)) return false;
      }
      return ParseOptionalCcMask(&dst.cc);
    }
    if (!PeekIs(Tok::Dot)) {
      return Fail(Diag::OperandAddressComponent, {last_end_, last_end_},
                  "ARL needs the write mask '.x' on its address register");
    }
    Advance();
    Token mask;
    if (!ExpectIdent("the write mask 'x'", &mask)) return false;
    if (!Is(Text(mask), "x")) {
      return Fail(
          Diag::OperandAddressComponent, RangeOf(mask),
          fmt::format("address register write mask '{}' is invalid; only '.x' exists", Text(mask)));
    }
    dst.mask = 1;
    return true;
  }

  bool IsBindingStart(const Token& t) const {
    std::string_view w = Text(t);
    if (Is(w, "state") || Is(w, "program") || Is(w, "result")) return true;
    return Is(w, vp() ? "vertex" : "fragment");
  }

  int AddImplicit(VarKind kind, const Binding& b) { return AddSimpleVariable(kind, nullptr, &b); }

  // An operand's own binding ("vertex.normal", "{1, 2}"): an unnamed variable of `kind`.
  [[nodiscard]] bool ParseImplicitSrc(VarKind kind, SrcOperand* out) {
    Binding b;
    bool ok = kind == VarKind::Attrib ? ParseAttribBinding(&b) : ParseParamSingleItem(false, &b);
    if (!ok) return false;
    if (relative_pending_) {
      relative_pending_ = false;
      out->var = AddRelativeArray(kind, b);
      out->indexed = true;
      out->relative = true;
      out->address_var = relative_.address_var;
      out->address_component = relative_.address_component;
      out->index = relative_.index;
      return true;
    }
    out->var = AddImplicit(kind, b);
    return true;
  }

  // The unnamed array behind a relatively addressed binding: one element per texture
  // coordinate set or generic attribute (the implementation's counts, Mesa's 8 and 16),
  // shared by every operand that indexes the same array.
  int AddRelativeArray(VarKind kind, const Binding& b) {
    const bool generic =
        b.kind == BindingKind::VertexAttrib && b.vertex_attrib == VertexAttrib::Generic;
    const int size = generic ? 16 : 8;
    for (size_t v = 0; v < program_->vars.size(); ++v) {
      const Variable& var = program_->vars[v];
      if (var.relative_array && var.kind == kind && var.bindings[0].kind == b.kind &&
          var.bindings[0].vertex_attrib == b.vertex_attrib &&
          var.bindings[0].fragment_attrib == b.fragment_attrib &&
          var.bindings[0].result == b.result) {
        return static_cast<int>(v);
      }
    }
    Binding element = b;
    const int index = AddSimpleVariable(kind, nullptr, &element);
    Variable& var = program_->vars[static_cast<size_t>(index)];
    var.is_array = true;
    var.relative_array = true;
    var.bindings.clear();
    for (int i = 0; i < size; ++i) {
      element.index = i;
      var.bindings.push_back(element);
    }
    return index;
  }

  // <srcReg> ::= <vertexAttribReg> | <temporaryReg> | <progParamReg>, with array access.
  [[nodiscard]] bool ParseSrcReg(bool allow_constant, SrcOperand* out) {
    SrcOperand& src = *out;
    const Token& t = Peek();
    if (t.kind == Tok::Ident) {
      std::string_view w = Text(t);
      if (IsAttribKeyword(t)) return ParseImplicitSrc(VarKind::Attrib, out);
      if (Is(w, "state") || Is(w, "program")) return ParseImplicitSrc(VarKind::Param, out);
      if (Is(w, "result")) {
        Token start = Peek();
        Binding ignored;
        if (!ParseResultBinding(&ignored)) return false;
        relative_pending_ = false;
        return Fail(Diag::OperandSrcWriteOnly, RangeOf(start),
                    "cannot read a result register: results are write-only");
      }
      if ((Is(w, "vertex") || Is(w, "fragment")) && !symbols_.Contains(w) && PeekIs(Tok::Dot, 1)) {
        return Fail(Diag::BindingStage, RangeOf(t),
                    fmt::format("'{}.*' bindings exist only in {} programs", w,
                                Is(w, "vertex") ? "vertex" : "fragment"));
      }
      Token name = Advance();
      if (!ResolveName(name, &src.var)) return false;
      const Variable& v = program_->vars[static_cast<size_t>(src.var)];
      if (v.kind == VarKind::Output) {
        return Fail(Diag::OperandSrcWriteOnly, RangeOf(name),
                    fmt::format("cannot read output '{}': results are write-only", Text(name)));
      }
      if (v.kind == VarKind::Address) {
        return Fail(Diag::DeclWrongKind, RangeOf(name),
                    fmt::format("address register '{}' can only be used to index a PARAM array, "
                                "as in 'array[{}.x]'",
                                Text(name), Text(name)));
      }
      if (PeekIs(Tok::LBracket)) {
        if (!v.is_array) {
          return Fail(Diag::OperandNotArray, RangeOf(Peek()),
                      fmt::format("'{}' is not a PARAM array and cannot be indexed", Text(name)));
        }
        return ParseArrayMember(&src, v, name);
      }
      if (v.is_array) {
        return Fail(
            Diag::OperandArrayNoIndex, RangeOf(name),
            fmt::format("PARAM array '{}' must be indexed, as in '{}[0]'", Text(name), Text(name)));
      }
      return true;
    }
    if (allow_constant && (t.kind == Tok::Minus || t.kind == Tok::Plus) &&
        (PeekIs(Tok::Integer, 1) || PeekIs(Tok::Float, 1))) {
      return Fail(Diag::OperandNegatedConstant, RangeOf(t),
                  "an inline scalar constant takes no sign of its own; the operand has one "
                  "sign, before the constant");
    }
    if (allow_constant &&
        (t.kind == Tok::Integer || t.kind == Tok::Float || t.kind == Tok::LBrace)) {
      return ParseImplicitSrc(VarKind::Param, out);
    }
    return FailExpected("a source operand");
  }

  // <progParamArrayMem> ::= <progParamArrayAbs> | <progParamArrayRel>
  [[nodiscard]] bool ParseArrayMember(SrcOperand* src, const Variable& v, const Token& name) {
    Advance();  // '['
    src->indexed = true;
    if (PeekIs(Tok::Integer)) {
      Token n = Advance();
      if (!ParseIntegerToken(n, &src->index)) return false;
      if (static_cast<size_t>(src->index) >= v.bindings.size()) {
        return Fail(
            Diag::OperandIndexRange, RangeOf(n),
            fmt::format("index {} is out of bounds for array '{}' of {} element{}", src->index,
                        Text(name), v.bindings.size(), v.bindings.size() == 1 ? "" : "s"));
      }
    } else if (PeekIs(Tok::Ident)) {
      if (!ParseRelativeIndex(src)) return false;
    } else {
      return FailExpected("an array index");
    }
    return Expect(Tok::RBracket, "']' after the array index");
  }
  // <progParamArrayRel> ::= <addrReg> <addrComponent> <addrRegRelOffset>
  [[nodiscard]] bool ParseRelativeIndex(SrcOperand* src, bool attribute_array = false) {
    Token addr = Advance();
    if (fp() && attribute_array) return ParseLoopIndex(addr, src);
    if (fp()) {
      return Fail(Diag::OperandRelativeFp, RangeOf(addr),
                  "relative addressing exists only in vertex programs; fragment programs index "
                  "arrays with constants");
    }
    int var = 0;
    if (!ResolveName(addr, &var)) return false;
    if (program_->vars[static_cast<size_t>(var)].kind != VarKind::Address) {
      return Fail(Diag::DeclWrongKind, RangeOf(addr),
                  fmt::format("'{}' is a {}, not an address register; relative indices use an "
                              "ADDRESS register",
                              Text(addr), KindName(program_->vars[static_cast<size_t>(var)].kind)));
    }
    src->relative = true;
    src->address_var = var;
    if (!PeekIs(Tok::Dot)) {
      return Fail(Diag::OperandAddressComponent, {last_end_, last_end_},
                  fmt::format("address register '{}' needs the component '.x'", Text(addr)));
    }
    Advance();
    Token comp;
    if (!ExpectIdent("the address component 'x'", &comp)) return false;
    if (program_->Nv() && Text(comp).size() == 1 &&
        std::string_view("xyzw").find(Text(comp)[0]) != std::string_view::npos) {
      src->address_component = static_cast<uint8_t>(std::string_view("xyzw").find(Text(comp)[0]));
    } else if (!Is(Text(comp), "x")) {
      return Fail(Diag::OperandAddressComponent, RangeOf(comp),
                  fmt::format("address component '{}' is invalid; only '.x' exists", Text(comp)));
    }
    // <addrRegRelOffset> ::= "" | "+" <addrRegPosOffset> | "-" <addrRegNegOffset>
    if (PeekIs(Tok::Plus) || PeekIs(Tok::Minus)) {
      bool negative = Is(Text(Advance()), "-");
      Token n;
      int offset = 0;
      if (!ExpectIntegerValue("an offset", &n, &offset)) return false;
      if ((negative && offset > 64) || (!negative && offset > 63)) {
        return Fail(Diag::OperandOffsetRange, RangeOf(n),
                    fmt::format("relative offset {}{} is out of range; offsets go from -64 to +63",
                                negative ? "-" : "+", offset));
      }
      src->index = negative ? -offset : offset;
    }
    return true;
  }

  // NV_fragment_program2's "A0.x" (+ offset) in fragment.texcoord[A0.x+n]: the predefined
  // address register holding the innermost LOOP's index (3.11.3.Y); only its x exists.
  [[nodiscard]] bool ParseLoopIndex(const Token& addr, SrcOperand* src) {
    if (!Is(Text(addr), "A0")) {
      return Fail(Diag::DeclWrongKind, RangeOf(addr),
                  fmt::format("'{}' is not an address register; fragment programs index "
                              "fragment.texcoord with the loop index 'A0.x'",
                              Text(addr)));
    }
    const Symbol* symbol = symbols_.Find("A0");
    src->address_var = symbol ? symbol->var : AddSimpleVariable(VarKind::Address, &addr, nullptr);
    if (src->address_var < 0) return false;  // poisoned: already reported
    src->relative = true;
    Token comp;
    if (!ExpectDot("A0") || !ExpectIdent("the address component 'x'", &comp)) return false;
    if (!Is(Text(comp), "x")) {
      return Fail(
          Diag::OperandAddressComponent, RangeOf(comp),
          fmt::format("address component '{}' is invalid; the loop index is 'A0.x'", Text(comp)));
    }
    if (PeekIs(Tok::Plus) || PeekIs(Tok::Minus)) {
      bool negative = Is(Text(Advance()), "-");
      Token n;
      int offset = 0;
      if (!ExpectIntegerValue("an offset", &n, &offset)) return false;
      src->index = negative ? -offset : offset;
    }
    return true;
  }

  // <swizzleSrcReg> / <vectorSrcReg> ::= <optionalSign> <srcReg> <swizzleSuffix>
  // <scalarSrcReg> ::= <optionalSign> <srcReg> <scalarSuffix>
  [[nodiscard]] bool ParseSwizzleSrcReg(bool scalar, std::string_view opname, SrcOperand* out) {
    uint32_t begin = Peek().begin;
    bool negate = false;
    if (PeekIs(Tok::Minus) || PeekIs(Tok::Plus)) negate = Is(Text(Advance()), "-");
    // <instOperandAbsV> ::= <optSign> "|" <instOperandBaseV> "|": |-x| is |x|.
    if (PeekIs(Tok::Bar)) {
      Token bar = Advance();
      if (!program_->Nv()) {
        return Fail(Diag::SyntaxNvConstruct, RangeOf(bar),
                    fmt::format("the absolute value '|operand|' needs OPTION {}",
                                NvOptionName(vp(), OpLevel::Nv)));
      }
      if (PeekIs(Tok::Minus) || PeekIs(Tok::Plus)) Advance();
      if (!ParseSwizzleSrcReg(scalar, opname, out)) return false;
      if (!Expect(Tok::Bar, "'|' closing the absolute value")) return false;
      out->abs = true;
      out->negate = negate;
      out->range = {begin, last_end_};
      return true;
    }
    SrcOperand& src = *out;
    if (!ParseSrcReg(/*allow_constant=*/true, &src)) return false;
    src.negate = negate;
    src.range = {begin, last_end_};
    if (PeekIs(Tok::Dot)) {
      Advance();
      Token swz;
      if (!ExpectIdent("a swizzle", &swz) || !ParseSwizzle(swz, scalar, opname, &src)) {
        return false;
      }
    } else if (scalar && program_->Nv() && IsInlineScalar(src)) {
      // <paramUseS> ::= <constantScalar> under the NV options: no suffix needed.
      src.swizzle = {Swz::X, Swz::X, Swz::X, Swz::X};
    } else if (scalar) {
      return Fail(
          Diag::OperandScalarRequired, src.range,
          fmt::format(
              "'{}' takes a scalar operand: select one component, as in '{}.x'", opname,
              std::string_view(text_).substr(src.range.begin, src.range.end - src.range.begin)));
    }
    return true;
  }

  [[nodiscard]] bool ParseSwizzle(const Token& t, bool scalar, std::string_view opname,
                                  SrcOperand* src) {
    std::string_view s = Text(t);
    int sets = 0;
    std::array<Swz, 4> swz{};
    for (size_t i = 0; i < s.size() && i < 4; ++i) {
      int set = 0;
      int comp = ComponentOf(s[i], &set);
      if (comp < 0) {
        return Fail(Diag::OperandBadSwizzle, RangeOf(t),
                    fmt::format("'{}' is not a swizzle: use one or four of {}", s,
                                fp() ? "x, y, z, w (or r, g, b, a)" : "x, y, z, w"));
      }
      sets |= set;
      swz[i] = static_cast<Swz>(comp);
    }
    if (s.size() != 1 && s.size() != 4) {
      return Fail(Diag::OperandBadSwizzle, RangeOf(t),
                  fmt::format("swizzle '{}' has {} components; a swizzle selects one or four", s,
                              s.size()));
    }
    if (!CheckComponentSets(t, sets, "swizzle")) return false;
    if (scalar && s.size() != 1) {
      return Fail(
          Diag::OperandScalarRequired, RangeOf(t),
          fmt::format("'{}' takes a scalar operand: '.{}' selects four components; select one",
                      opname, s));
    }
    if (s.size() == 1) {
      src->swizzle = {swz[0], swz[0], swz[0], swz[0]};
    } else {
      src->swizzle = swz;
    }
    return true;
  }

  // SWZ: <srcReg> "," <extendedSwizzle> (no sign, no suffix on the register)
  [[nodiscard]] bool ParseSwzSource(SrcOperand* out) {
    uint32_t begin = Peek().begin;
    if (PeekIs(Tok::Minus) || PeekIs(Tok::Plus)) {
      return Fail(Diag::OperandExtSwizzle, RangeOf(Peek()),
                  "SWZ takes a register without sign; negate components in the extended "
                  "swizzle ('-x')");
    }
    SrcOperand& src = *out;
    if (!ParseSrcReg(/*allow_constant=*/true, &src)) return false;
    src.range = {begin, last_end_};
    if (PeekIs(Tok::Dot)) {
      return Fail(Diag::OperandExtSwizzle, RangeOf(Peek()),
                  "SWZ takes a register without suffix; the swizzle is the four selectors that "
                  "follow");
    }
    // <extendedSwizzle> ::= <extSwizComp> "," <extSwizComp> "," <extSwizComp> "," <extSwizComp>
    int sets = 0;
    for (int i = 0; i < 4; ++i) {
      if (!PeekIs(Tok::Comma)) {
        return Fail(Diag::OperandExtSwizzle,
                    PeekIs(Tok::Semicolon) ? Range{last_end_, last_end_} : RangeOf(Peek()),
                    fmt::format("SWZ needs four selectors (0, 1, or a component, each with an "
                                "optional sign); found {}",
                                i));
      }
      Advance();  // ','
      bool negative = false;
      if (PeekIs(Tok::Minus) || PeekIs(Tok::Plus)) negative = Is(Text(Advance()), "-");
      Swz value = Swz::Zero;
      if (!ParseExtSwizzleSelector(&sets, &value)) return false;
      Advance();
      src.swizzle[static_cast<size_t>(i)] = value;
      src.component_negate[static_cast<size_t>(i)] = negative;
    }
    if (PeekIs(Tok::Comma)) {
      return Fail(Diag::OperandExtSwizzle, RangeOf(Peek()), "SWZ takes exactly four selectors");
    }
    return true;
  }
  // <extSwizComp>'s selector (not consumed): 0, 1 or a component; *sets gathers the
  // component sets seen so far.
  [[nodiscard]] bool ParseExtSwizzleSelector(int* sets, Swz* value) {
    const Token& sel = Peek();
    std::string_view s = Text(sel);
    if (sel.kind == Tok::Integer && (Is(s, "0") || Is(s, "1"))) {
      *value = Is(s, "0") ? Swz::Zero : Swz::One;
      return true;
    }
    if (sel.kind != Tok::Ident || s.size() != 1) {
      return Fail(Diag::OperandExtSwizzle, RangeOf(sel),
                  fmt::format("{} is not an extended swizzle selector; use 0, 1 or a single "
                              "component name",
                              Describe(sel)));
    }
    int set = 0;
    int comp = ComponentOf(s[0], &set);
    if (comp < 0) {
      return Fail(Diag::OperandExtSwizzle, RangeOf(sel),
                  fmt::format("'{}' is not an extended swizzle selector; use 0, 1 or one of {}", s,
                              fp() ? "x, y, z, w, r, g, b, a" : "x, y, z, w"));
    }
    if (set == 2 && vp()) {
      return Fail(
          Diag::OperandRgbaVp, RangeOf(sel),
          fmt::format("selector '{}' is an rgba name, which only fragment programs accept", s));
    }
    if ((*sets | set) == 3) {
      return Fail(Diag::OperandSwizzleMix, RangeOf(sel),
                  "extended swizzle mixes xyzw and rgba component names");
    }
    *sets |= set;
    *value = static_cast<Swz>(comp);
    return true;
  }

  // <texImageUnit> ::= "texture" <optTexImageUnitNum>
  [[nodiscard]] bool ParseTexImageUnit(Instruction* inst) {
    if (!PeekIdent("texture")) return FailExpected("a texture unit ('texture' or 'texture[n]')");
    Token kw = Advance();
    inst->unit_range = RangeOf(kw);
    inst->tex_unit = 0;
    if (PeekIs(Tok::LBracket)) {
      Token n;
      if (!ParseBracketIndex("a texture image unit number", &n)) return false;
      if (!ParseIntegerToken(n, &inst->tex_unit)) return false;
      inst->unit_range = RangeOf(n);
    }
    return true;
  }

  // <texTarget> ::= "1D" | "2D" | "3D" | "CUBE" | "RECT" (| "SHADOW1D" | "SHADOW2D" |
  //                 "SHADOWRECT" with ARB_fragment_program_shadow)
  [[nodiscard]] bool ParseTexTarget(Instruction* inst) {
    // texture_targets.def in its order: 1D 2D 3D CUBE RECT SHADOW1D SHADOW2D SHADOWRECT.
    static const std::vector<std::string_view> names = [] {
      std::vector<std::string_view> all;
#define ARBVP_TEX_TARGET(Name, ...) all.push_back(TexTargetName(TexTarget::Name));
#include "arbiter/arbvp/texture_targets.def"
#undef ARBVP_TEX_TARGET
      return all;
    }();
    const Token& t = Peek();
    if (t.kind == Tok::Ident) {
      for (size_t i = 0; i < names.size(); ++i) {
        if (Text(t) == names[i]) {
          inst->target = static_cast<TexTarget>(i);
          inst->target_range = RangeOf(Advance());
          return true;
        }
      }
    }
    std::string hint = t.kind == Tok::Ident || t.kind == Tok::Integer ? ClosestMatch(Text(t), names)
                                                                      : std::string();
    return Fail(Diag::TextureUnknownTarget, RangeOf(t),
                fmt::format("{} is not a texture target; expected {}{}", Describe(t),
                            JoinAlternatives(names),
                            hint.empty() ? "" : fmt::format(" (did you mean '{}'?)", hint)));
  }

  const SourceFile& source_;
  const std::string& text_;
  // The tokens the parser has looked at: a small window that the lexer refills, so that no
  // program-sized token array is kept.
  static constexpr size_t kWindow = 32;
  static constexpr size_t kTypicalStatements = 32;
  Lexer lexer_;
  std::array<Token, kWindow> window_{};
  bool lexical_errors_reported_ = false;                   // all of them: the lexer is silent
  size_t fetched_ = 0;                                     // tokens lexed so far
  size_t eof_index_ = std::numeric_limits<size_t>::max();  // index of the Eof token, once lexed
  ProgramKind kind_;
  DiagnosticSink* sink_;
  size_t pos_ = 0;
  uint32_t last_end_ = 0;
  // A relative index of an attribute or result array, parsed with its binding, until the
  // operand that holds the binding takes it.
  SrcOperand relative_;
  bool relative_pending_ = false;
  std::unique_ptr<Program> program_;
  SymbolTable symbols_;
};

}  // namespace

bool IsReservedWord(std::string_view word, ProgramKind kind) {
  // Keywords have 3 ("END") to 8 ("fragment") characters, opcodes 3 and 7 ("MOV_SAT"): most
  // variable names are rejected here, without a comparison (one call per declared name).
  if (word.size() < 3 || word.size() > 8) return false;
  auto first = static_cast<unsigned char>(word[0]);
  if (first >= 128) return false;
  const KeywordLengths& lengths =
      kind == ProgramKind::Vertex ? kVpKeywordLengths : kFpKeywordLengths;
  if ((lengths.by_first[first] >> word.size()) & 1u) {
    const auto& keywords = kind == ProgramKind::Vertex ? kVpKeywords : kFpKeywords;
    for (std::string_view k : keywords) {
      if (Is(word, k)) return true;
    }
  }
  if (word[0] < 'A' || word[0] > 'Z') return false;  // opcodes are upper case
  std::string_view base = word;
  bool sat = base.size() > 4 && Is(base.substr(base.size() - 4), "_SAT");
  if (sat) {
    if (kind == ProgramKind::Vertex) return false;
    base.remove_suffix(4);
  }
  Opcode op;
  if (!LookupOpcode(base, &op) || !OpcodeInStage(op, kind)) return false;
  // KIL has no _SAT form.
  return !(sat && op == Opcode::KIL);
}

std::unique_ptr<Program> ParseProgram(const compiler::SourceFile& source, ProgramKind kind,
                                      Range header, compiler::DiagnosticSink* sink) {
  return Parser(source, kind, header, sink).Run(header);
}

}  // namespace arbiter::arbvp
