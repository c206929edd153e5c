// Recursive-descent parser of ARB vertex and fragment programs (ARBvp 2.14.2, ARBfp 3.11.2).
// One function per grammar symbol, its production quoted above it. On an error the
// statement is abandoned and parsing resumes after the next ';'.
#include "parser.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "diag.h"
#include "suggest.h"

namespace arbiter::arbvp {
namespace {

using compiler::DiagnosticSink;
using compiler::SourceFile;

// A <floatConstant>'s value, rounded to nearest as strtof (what Mesa's lexer uses) rounds it.
// from_chars rounds the same and needs no NUL-terminated copy of the text; the values it
// leaves unset (out of range: overflow, underflow) go to strtof, which gives +inf on
// overflow, as GL would.
float ParseFloatText(std::string_view text) {
  float value = 0.0f;
  auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec == std::errc()) return value;
  std::string copy(text);
  return std::strtof(copy.c_str(), nullptr);
}

// Thrown after an error has been reported, to abandon the current statement.
struct StatementError {};

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
  Range decl;
};

constexpr std::string_view kVpKeywords[] = {"ADDRESS", "ALIAS",  "ATTRIB", "END",
                                            "OPTION",  "OUTPUT", "PARAM",  "TEMP",
                                            "program", "result", "state",  "vertex"};
constexpr std::string_view kFpKeywords[] = {"ALIAS",   "ATTRIB", "END",   "OPTION",
                                            "OUTPUT",  "PARAM",  "TEMP",  "fragment",
                                            "program", "result", "state", "texture"};

class Parser {
 public:
  // The parser lexes as it goes, keeping only a window of tokens (see ReportLexicalErrors).
  Parser(const SourceFile& source, ProgramKind kind, Range header, DiagnosticSink* sink)
      : source_(source),
        text_(source.text()),
        lexer_(source, header.end, sink),
        kind_(kind),
        sink_(sink) {}

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
  const Token& Peek(size_t ahead = 0) {
    size_t i = pos_ + ahead;
    if (i >= fetched_) [[unlikely]]
      Fetch(i);
    return window_[std::min(i, eof_index_) % kWindow];
  }
  // Lexes up to token i (or Eof), and on as far as the window allows: lexing a batch of
  // tokens per call keeps the call out of most Peeks.
  [[gnu::noinline]] void Fetch(size_t i) {
    size_t last = std::max(i, pos_ + kWindow - 3);  // keeps tokens pos_ - 2 on intact
    while (fetched_ <= last && fetched_ <= eof_index_) {
      size_t slot = fetched_ % kWindow;
      size_t count = std::min(last + 1 - fetched_, kWindow - slot);  // contiguous slots
      size_t got = lexer_.Fill(&window_[slot], count);
      fetched_ += got;
      if (window_[slot + got - 1].kind == Tok::Eof) eof_index_ = fetched_ - 1;
    }
  }
  std::string_view Text(const Token& t) const {
    return std::string_view(text_.data() + t.begin, t.end - t.begin);  // the lexer's bounds
  }
  bool PeekIs(Tok kind, size_t ahead = 0) { return Peek(ahead).kind == kind; }
  bool PeekIdent(std::string_view word, size_t ahead = 0) {
    return Peek(ahead).kind == Tok::Ident && Text(Peek(ahead)) == word;
  }
  Token Advance() {
    Token t = Peek();
    if (pos_ < eof_index_) ++pos_;
    last_end_ = t.end;
    return t;
  }
  bool Accept(Tok kind) {
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
  [[noreturn]] void Fail(Diag diag, Range range, std::string message) {
    ReportDiagnostic(diag, range, std::move(message));
    throw StatementError{};
  }
  void Report(Diag diag, Range range, std::string message) {
    ReportDiagnostic(diag, range, std::move(message));
  }
  [[noreturn]] void FailExpected(std::string_view what) {
    const Token& t = Peek();
    Fail(Diag::SyntaxExpected, RangeOf(t), fmt::format("expected {}, found {}", what, Describe(t)));
  }
  Token Expect(Tok kind, std::string_view what) {
    if (!PeekIs(kind)) FailExpected(what);
    return Advance();
  }
  Token ExpectIdent(std::string_view what) { return Expect(Tok::Ident, what); }
  // Expects one of `words` (an identifier); reports the alternatives otherwise.
  Token ExpectWord(std::initializer_list<std::string_view> word_list, std::string_view context,
                   Diag diag = Diag::BindingUnknown) {
    const Token& t = Peek();
    if (t.kind == Tok::Ident) {
      for (std::string_view w : word_list) {
        if (Text(t) == w) return Advance();
      }
    }
    return ExpectWordSlow(std::vector<std::string_view>(word_list), context, diag);
  }
  Token ExpectWordSlow(const std::vector<std::string_view>& words, std::string_view context,
                       Diag diag = Diag::BindingUnknown) {
    const Token& t = Peek();
    if (t.kind == Tok::Ident) {
      for (std::string_view w : words) {
        if (Text(t) == w) return Advance();
      }
      std::string hint = ClosestMatch(Text(t), words);
      Fail(diag, RangeOf(t),
           fmt::format("unknown {} '{}'; expected {}{}", context, Text(t), JoinAlternatives(words),
                       hint.empty() ? "" : fmt::format(" (did you mean '{}'?)", hint)));
    }
    FailExpected(fmt::format("{} ({})", context, JoinAlternatives(words)));
  }
  int ParseIntegerToken(const Token& t) {
    int value = 0;
    auto [ptr, ec] = std::from_chars(text_.data() + t.begin, text_.data() + t.end, value);
    if (ec != std::errc() || ptr != text_.data() + t.end) {
      Fail(Diag::BindingIndexRange, RangeOf(t), fmt::format("integer {} is too large", Text(t)));
    }
    return value;
  }
  Token ExpectInteger(std::string_view what) {
    if (PeekIs(Tok::Float)) {
      Fail(Diag::SyntaxExpected, RangeOf(Peek()),
           fmt::format("expected {} (an integer), found {}", what, Describe(Peek())));
    }
    if (!PeekIs(Tok::Integer)) FailExpected(fmt::format("{} (an integer)", what));
    return Advance();
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
      if (t.kind == Tok::Ident && Text(t) == "END") {
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
      try {
        if (t.kind == Tok::Ident && Text(t) == "OPTION") {
          ParseOption(seen_statement);
        } else {
          seen_statement = true;
          ParseStatement();
        }
      } catch (const StatementError&) {
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
    if (s == "END" || s == "OPTION" || s == "ATTRIB" || s == "PARAM" || s == "TEMP" ||
        s == "ADDRESS" || s == "OUTPUT" || s == "ALIAS")
      return true;
    Opcode op;
    if (s.size() > 4 && s.substr(s.size() - 4) == "_SAT") s.remove_suffix(4);
    return LookupOpcode(s, &op);
  }

  // Every statement ends with ';'. A missing one points just after the previous token; when
  // the next token begins a statement on a later line, parsing goes on from there.
  // `what` names the statement ("ATTRIB statement"); `quoted`, when given, is put in
  // quotes before it ("'MOV' instruction"). Messages are built only on failure.
  void ExpectSemicolon(std::string_view what, std::string_view quoted = {}) {
    if (Accept(Tok::Semicolon)) return;
    const Token& next = Peek();
    if (next.kind == Tok::Comma) {
      Fail(Diag::SyntaxExpected, RangeOf(next),
           fmt::format("expected ';' after the {}{}, found ',': too many operands", Quoted(quoted),
                       what));
    }
    Report(
        Diag::SyntaxMissingSemicolon, {last_end_, last_end_},
        fmt::format("expected ';' after the {}{}, found {}", Quoted(quoted), what, Describe(next)));
    bool later_line = source_.Locate(next.begin).line > source_.Locate(last_end_).line;
    if ((later_line && StartsStatement(next)) || next.kind == Tok::Eof) return;
    throw StatementError{};
  }

  // <option> ::= "OPTION" <identifier> ";"
  void ParseOption(bool after_statement) {
    Token keyword = Advance();
    if (after_statement) {
      Report(Diag::SyntaxOptionPlacement, RangeOf(keyword),
             "OPTION must come before every other statement of the program");
    }
    Token name = ExpectIdent("an option name after 'OPTION'");
    OptionId id;
    if (!LookupOption(Text(name), &id)) {
      std::vector<std::string_view> names;
      for (const OptionInfo& info : AllOptions()) names.push_back(info.spelling);
      std::string hint = ClosestMatch(Text(name), names);
      std::string why;
      if (Text(name).substr(0, 3) == "NV_") {
        why = "; NV program options are not supported";
      } else if (!hint.empty()) {
        why = fmt::format(" (did you mean '{}'?)", hint);
      }
      Report(Diag::OptionUnknown, RangeOf(name),
             fmt::format("unknown program option '{}'{}", Text(name), why));
    } else {
      program_->options.push_back({id, RangeOf(name)});
    }
    ExpectSemicolon("OPTION statement");
  }

  // <statement> ::= <instruction> ";" | <namingStatement> ";"
  void ParseStatement() {
    const Token& t = Peek();
    if (t.kind != Tok::Ident) FailExpected("an instruction or a declaration");
    std::string_view word = Text(t);
    if (word == "ATTRIB") return ParseAttribStatement();
    if (word == "PARAM") return ParseParamStatement();
    if (word == "TEMP") return ParseVarListStatement(VarKind::Temp);
    if (word == "ADDRESS") {
      if (fp() && !symbols_.count("ADDRESS")) {
        Fail(Diag::SyntaxStatementStage, RangeOf(t),
             "ADDRESS declarations exist only in vertex programs: fragment programs have no "
             "address registers");
      }
      if (vp()) return ParseVarListStatement(VarKind::Address);
    }
    if (word == "OUTPUT") return ParseOutputStatement();
    if (word == "ALIAS") return ParseAliasStatement();
    ParseInstruction();
  }

  // ---- names ---------------------------------------------------------------------------

  // <establishName> ::= <identifier>; returns false (after reporting) when the name is taken.
  bool ParseEstablishName(Token* name_out) {
    Token name = ExpectIdent("a variable name");
    *name_out = name;
    std::string_view word = Text(name);
    if (IsReservedWord(word, kind_)) {
      Fail(Diag::SyntaxReservedName, RangeOf(name),
           fmt::format("'{}' is a reserved word and cannot name a variable", word));
    }
    auto it = symbols_.find(word);
    if (it != symbols_.end()) {
      compiler::Diagnostic* d = ReportDiagnostic(Diag::DeclRedeclared, RangeOf(name),
                                                 fmt::format("redeclaration of '{}'", word));
      if (d)
        d->notes.push_back(
            {&source_, it->second.decl, fmt::format("'{}' first declared here", word)});
      return false;
    }
    return true;
  }

  int AddVariable(Variable var, const Token* name) {
    int index = static_cast<int>(program_->vars.size());
    program_->vars.push_back(std::move(var));
    if (name) symbols_[std::string(Text(*name))] = {index, RangeOf(*name)};
    return index;
  }
  void Poison(const Token& name) {
    symbols_.emplace(std::string(Text(name)), Symbol{-1, RangeOf(name)});
  }

  // Looks up <establishedName>; reports undeclared names (with a suggestion).
  int ResolveName(const Token& name) {
    auto it = symbols_.find(Text(name));
    if (it == symbols_.end()) {
      std::vector<std::string_view> names;
      for (const auto& [n, s] : symbols_) names.push_back(n);
      std::sort(names.begin(), names.end());
      std::string hint = ClosestMatch(Text(name), names);
      Fail(Diag::DeclUndeclared, RangeOf(name),
           fmt::format("use of undeclared identifier '{}'{}", Text(name),
                       hint.empty() ? "" : fmt::format("; did you mean '{}'?", hint)));
    }
    if (it->second.var < 0) throw StatementError{};  // poisoned: already reported
    return it->second.var;
  }

  // ---- declarations ----------------------------------------------------------------------

  // Declares the variable of an ATTRIB or OUTPUT statement (unless its name was taken).
  void AddBoundVariable(const Token& name, bool fresh, VarKind kind, const Binding& binding) {
    if (!fresh) return;
    Variable var;
    var.name = std::string(Text(name));
    var.kind = kind;
    var.decl = RangeOf(name);
    var.bindings.push_back(binding);
    AddVariable(std::move(var), &name);
  }

  // <ATTRIB_statement> ::= "ATTRIB" <establishName> "=" <vtxAttribBinding>|<fragAttribBinding>
  void ParseAttribStatement() {
    Advance();
    Token name;
    bool fresh = ParseEstablishName(&name);
    Expect(Tok::Equals, "'=' after the attribute name");
    try {
      const Token& b = Peek();
      if (!IsAttribKeyword(b)) {
        if (b.kind == Tok::Ident && Text(b) == (vp() ? "fragment" : "vertex")) {
          Fail(Diag::BindingStage, RangeOf(b),
               fmt::format("'{}.*' bindings exist only in {} programs; {} programs bind {}",
                           Text(b), vp() ? "fragment" : "vertex", vp() ? "vertex" : "fragment",
                           vp() ? "vertex.*" : "fragment.*"));
        }
        if (b.kind == Tok::Ident && (Text(b) == "state" || Text(b) == "program")) {
          Fail(Diag::DeclWrongKind, RangeOf(b),
               fmt::format("ATTRIB binds {} attributes; '{}' bindings are declared with PARAM",
                           vp() ? "vertex.*" : "fragment.*", Text(b)));
        }
        if (b.kind == Tok::Ident && Text(b) == "result") {
          Fail(Diag::DeclWrongKind, RangeOf(b),
               "ATTRIB binds attributes; result bindings are declared with OUTPUT");
        }
        FailExpected(vp() ? "a vertex attribute binding ('vertex.*')"
                          : "a fragment attribute binding ('fragment.*')");
      }
      AddBoundVariable(name, fresh, VarKind::Attrib, ParseAttribBinding());
    } catch (const StatementError&) {
      if (fresh) Poison(name);
      throw;
    }
    ExpectSemicolon("ATTRIB statement");
  }

  // <OUTPUT_statement> ::= "OUTPUT" <establishName> "=" <resultBinding>
  void ParseOutputStatement() {
    Advance();
    Token name;
    bool fresh = ParseEstablishName(&name);
    Expect(Tok::Equals, "'=' after the output name");
    try {
      if (!PeekIdent("result")) FailExpected("a result binding ('result.*')");
      AddBoundVariable(name, fresh, VarKind::Output, ParseResultBinding());
    } catch (const StatementError&) {
      if (fresh) Poison(name);
      throw;
    }
    ExpectSemicolon("OUTPUT statement");
  }

  // <TEMP_statement> ::= "TEMP" <varNameList>; <ADDRESS_statement> likewise
  // <varNameList> ::= <establishName> | <establishName> "," <varNameList>
  void ParseVarListStatement(VarKind kind) {
    Token keyword = Advance();
    do {
      Token name;
      if (ParseEstablishName(&name)) {
        Variable var;
        var.name = std::string(Text(name));
        var.kind = kind;
        var.decl = RangeOf(name);
        AddVariable(std::move(var), &name);
      }
    } while (Accept(Tok::Comma));
    ExpectSemicolon("statement", Text(keyword));
  }

  // <ALIAS_statement> ::= "ALIAS" <establishName> "=" <establishedName>
  void ParseAliasStatement() {
    Advance();
    Token name;
    bool fresh = ParseEstablishName(&name);
    Expect(Tok::Equals, "'=' after the alias name");
    Token target = ExpectIdent("the name of a declared variable");
    auto it = symbols_.find(Text(target));
    if (it == symbols_.end()) {
      if (fresh) Poison(name);
      Fail(Diag::DeclAliasUndeclared, RangeOf(target),
           fmt::format("ALIAS of undeclared identifier '{}'", Text(target)));
    }
    if (fresh) symbols_[std::string(Text(name))] = {it->second.var, RangeOf(name)};
    ExpectSemicolon("ALIAS statement");
  }

  // <PARAM_singleStmt>   ::= "PARAM" <establishName> <paramSingleInit>
  // <PARAM_multipleStmt> ::= "PARAM" <establishName> "[" <optArraySize> "]" <paramMultipleInit>
  void ParseParamStatement() {
    Advance();
    Token name;
    bool fresh = ParseEstablishName(&name);
    Variable var;
    var.name = std::string(Text(name));
    var.kind = VarKind::Param;
    var.decl = RangeOf(name);
    try {
      if (Accept(Tok::LBracket)) {
        var.is_array = true;
        int declared_size = -1;
        Token size_token{};
        if (!PeekIs(Tok::RBracket)) {
          size_token = ExpectInteger("an array size");
          declared_size = ParseIntegerToken(size_token);
          if (declared_size < 1) {
            Fail(Diag::ParamArraySize, RangeOf(size_token),
                 fmt::format("array '{}' must have at least one element", Text(name)));
          }
        }
        Expect(Tok::RBracket, "']' after the array size");
        Expect(Tok::Equals, "'=' after the array declaration");
        // <paramMultipleInit> ::= "=" "{" <paramMultInitList> "}"
        if (!PeekIs(Tok::LBrace)) {
          FailExpected("'{' and a list of bindings to initialise the array");
        }
        Advance();
        do {
          ParseParamMultipleItem(&var.bindings);
        } while (Accept(Tok::Comma));
        Expect(Tok::RBrace, "'}' or ',' in the array initialiser");
        if (declared_size >= 0 && static_cast<size_t>(declared_size) != var.bindings.size()) {
          Fail(Diag::ParamArraySize, RangeOf(size_token),
               fmt::format("array '{}' is declared with {} element{} but initialised with {} "
                           "binding{}",
                           Text(name), declared_size, declared_size == 1 ? "" : "s",
                           var.bindings.size(), var.bindings.size() == 1 ? "" : "s"));
        }
      } else {
        // <paramSingleInit> ::= "=" <paramSingleItemDecl>
        Expect(Tok::Equals, "'=' or '[' after the parameter name");
        var.bindings.push_back(ParseParamSingleItem(/*decl=*/true));
      }
    } catch (const StatementError&) {
      if (fresh) Poison(name);
      throw;
    }
    if (fresh) AddVariable(std::move(var), &name);
    ExpectSemicolon("PARAM statement");
  }

  // <paramSingleItemDecl> ::= <stateSingleItem> | <programSingleItem> | <paramConstDecl>
  // <paramSingleItemUse>  ::= <stateSingleItem> | <programSingleItem> | <paramConstUse>
  Binding ParseParamSingleItem(bool decl) {
    if (PeekIdent("state")) {
      std::vector<Binding> rows;
      ParseStateItem(&rows, /*multiple=*/false);
      return rows.front();
    }
    if (PeekIdent("program")) {
      std::vector<Binding> items;
      ParseProgramItem(&items, /*multiple=*/false);
      return items.front();
    }
    if (PeekIs(Tok::LBrace)) return ParseConstVector();
    if (decl &&
        (PeekIs(Tok::Minus) || PeekIs(Tok::Plus) || PeekIs(Tok::Integer) || PeekIs(Tok::Float))) {
      return ParseConstScalar(/*allow_sign=*/true);
    }
    if (!decl && (PeekIs(Tok::Integer) || PeekIs(Tok::Float))) {
      return ParseConstScalar(/*allow_sign=*/false);
    }
    FailExpected("a state binding, a program parameter or a constant");
  }

  // <paramMultipleItem> ::= <stateMultipleItem> | <programMultipleItem> | <paramConstDecl>
  void ParseParamMultipleItem(std::vector<Binding>* out) {
    if (PeekIdent("state")) return ParseStateItem(out, /*multiple=*/true);
    if (PeekIdent("program")) return ParseProgramItem(out, /*multiple=*/true);
    if (PeekIs(Tok::LBrace)) {
      out->push_back(ParseConstVector());
      return;
    }
    if (PeekIs(Tok::Minus) || PeekIs(Tok::Plus) || PeekIs(Tok::Integer) || PeekIs(Tok::Float)) {
      out->push_back(ParseConstScalar(/*allow_sign=*/true));
      return;
    }
    FailExpected("a state binding, a program parameter or a constant");
  }

  // <signedFloatConstant> ::= <optionalSign> <floatConstant>
  float ParseSignedFloat(bool allow_sign, Range* range) {
    uint32_t begin = Peek().begin;
    bool negative = false;
    if (PeekIs(Tok::Minus) || PeekIs(Tok::Plus)) {
      Token sign = Advance();
      if (!allow_sign) {
        Fail(Diag::OperandNegatedConstant, RangeOf(sign),
             "an inline scalar constant takes no sign of its own; negate the operand instead");
      }
      negative = Text(sign) == "-";
    }
    if (!PeekIs(Tok::Integer) && !PeekIs(Tok::Float)) FailExpected("a number");
    Token number = Advance();
    float value = ParseFloatText(Text(number));
    *range = {begin, number.end};
    return negative ? -value : value;
  }

  // <paramConstScalarDecl> ::= <signedFloatConstant>; <paramConstScalarUse> ::= <floatConstant>
  Binding ParseConstScalar(bool allow_sign) {
    Binding b;
    b.kind = BindingKind::Constant;
    float v = ParseSignedFloat(allow_sign, &b.range);
    b.value = {v, v, v, v};
    b.selector = b.range;
    return b;
  }

  // <paramConstVector> ::= "{" <signedFloatConstant> ("," <signedFloatConstant>){0,3} "}"
  Binding ParseConstVector() {
    Binding b;
    b.kind = BindingKind::Constant;
    Token open = Advance();
    b.value = {0.0f, 0.0f, 0.0f, 1.0f};
    int count = 0;
    do {
      Range r;
      float v = ParseSignedFloat(true, &r);
      if (count == 4) {
        Fail(Diag::ParamTooManyComponents, r, "a constant vector has at most four components");
      }
      b.value[static_cast<size_t>(count++)] = v;
    } while (Accept(Tok::Comma));
    Token close = Expect(Tok::RBrace, "'}' or ',' in the constant vector");
    b.range = {open.begin, close.end};
    b.selector = b.range;
    return b;
  }

  // Parses "[" <integer> "]" and returns the integer token.
  Token ParseBracketIndex(std::string_view what) {
    if (!PeekIs(Tok::LBracket)) FailExpected(fmt::format("'[' and {}", what));
    Advance();
    Token n = ExpectInteger(what);
    if (!PeekIs(Tok::RBracket)) FailExpected(fmt::format("']' after {}", what));
    Advance();
    return n;
  }
  // An optional "[" n "]": sets index/selector/indexed on the binding.
  void ParseOptionalIndex(Binding* b, std::string_view what) {
    if (!PeekIs(Tok::LBracket)) return;
    Token n = ParseBracketIndex(what);
    b->index = ParseIntegerToken(n);
    b->selector = RangeOf(n);
    b->indexed = true;
  }
  void ParseRequiredIndex(Binding* b, std::string_view what) {
    Token n = ParseBracketIndex(what);
    b->index = ParseIntegerToken(n);
    b->selector = RangeOf(n);
    b->indexed = true;
  }
  // Consumes "." <word> when the word after the dot is one of `words`.
  bool AcceptDotWord(std::initializer_list<std::string_view> words, std::string_view* got) {
    if (!PeekIs(Tok::Dot) || !PeekIs(Tok::Ident, 1)) return false;
    std::string_view w = Text(Peek(1));
    for (std::string_view candidate : words) {
      if (w == candidate) {
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
  void RejectUnknownSuffix(const std::vector<std::string_view>& words, std::string_view what) {
    if (!PeekIs(Tok::Dot) || !PeekIs(Tok::Ident, 1)) return;
    const Token& t = Peek(1);
    if (LooksLikeSwizzle(Text(t))) return;
    std::string hint = ClosestMatch(Text(t), words);
    Fail(Diag::BindingUnknown, RangeOf(t),
         fmt::format("unknown {} '{}'; expected {}{}", what, Text(t), JoinAlternatives(words),
                     hint.empty() ? "" : fmt::format(" (did you mean '{}'?)", hint)));
  }
  void ExpectDot(std::string_view after) {
    if (!PeekIs(Tok::Dot)) FailExpected(fmt::format("'.' after '{}'", after));
    Advance();
  }

  // ---- bindings ------------------------------------------------------------------------

  bool IsAttribKeyword(const Token& t) const {
    return t.kind == Tok::Ident && Text(t) == (vp() ? "vertex" : "fragment");
  }

  Binding ParseAttribBinding() {
    return vp() ? ParseVertexAttribBinding() : ParseFragmentAttribBinding();
  }

  // <vtxAttribBinding> ::= "vertex" "." <vtxAttribItem>
  Binding ParseVertexAttribBinding() {
    Token start = Advance();
    ExpectDot("vertex");
    Binding b;
    b.kind = BindingKind::VertexAttrib;
    Token item = ExpectWord(
        {"position", "weight", "normal", "color", "fogcoord", "texcoord", "matrixindex", "attrib"},
        "vertex attribute");
    std::string_view w = Text(item);
    b.selector = RangeOf(item);
    b.item = RangeOf(item);
    if (w == "position") {
      b.vertex_attrib = VertexAttrib::Position;
    } else if (w == "weight") {
      b.vertex_attrib = VertexAttrib::Weight;
      ParseOptionalIndex(&b, "a weight number");
    } else if (w == "normal") {
      b.vertex_attrib = VertexAttrib::Normal;
    } else if (w == "color") {
      std::string_view type;
      b.vertex_attrib = VertexAttrib::Color;
      if (AcceptDotWord({"primary", "secondary"}, &type) && type == "secondary") {
        b.vertex_attrib = VertexAttrib::SecondaryColor;
      }
      RejectUnknownSuffix({"primary", "secondary"}, "colour type");
    } else if (w == "fogcoord") {
      b.vertex_attrib = VertexAttrib::FogCoord;
    } else if (w == "texcoord") {
      b.vertex_attrib = VertexAttrib::TexCoord;
      ParseOptionalIndex(&b, "a texture coordinate number");
    } else if (w == "matrixindex") {
      b.vertex_attrib = VertexAttrib::MatrixIndex;
      ParseRequiredIndex(&b, "a matrix index number");
    } else {
      b.vertex_attrib = VertexAttrib::Generic;
      ParseRequiredIndex(&b, "a generic attribute number");
    }
    b.range = {start.begin, last_end_};
    return b;
  }

  // <fragAttribBinding> ::= "fragment" "." <fragAttribItem>
  Binding ParseFragmentAttribBinding() {
    Token start = Advance();
    ExpectDot("fragment");
    Binding b;
    b.kind = BindingKind::FragmentAttrib;
    Token item = ExpectWord({"color", "texcoord", "fogcoord", "position"}, "fragment attribute");
    std::string_view w = Text(item);
    b.selector = RangeOf(item);
    if (w == "color") {
      std::string_view type;
      b.fragment_attrib = FragmentAttrib::Color;
      if (AcceptDotWord({"primary", "secondary"}, &type) && type == "secondary") {
        b.fragment_attrib = FragmentAttrib::SecondaryColor;
      }
      RejectUnknownSuffix({"primary", "secondary"}, "colour type");
    } else if (w == "texcoord") {
      b.fragment_attrib = FragmentAttrib::TexCoord;
      ParseOptionalIndex(&b, "a texture coordinate number");
    } else if (w == "fogcoord") {
      b.fragment_attrib = FragmentAttrib::FogCoord;
    } else {
      b.fragment_attrib = FragmentAttrib::Position;
    }
    b.range = {start.begin, last_end_};
    return b;
  }

  // <resultBinding> (ARBvp): "result" "." ("position" | <resultColBinding> | "fogcoord" |
  //                          "pointsize" | "texcoord" <optTexCoordNum>)
  // <resultBinding> (ARBfp): "result" "." ("color" | "depth"); "color" "[" n "]" with
  //                          ARB_draw_buffers
  Binding ParseResultBinding() {
    Token start = Advance();
    ExpectDot("result");
    Binding b;
    b.kind = BindingKind::Result;
    if (vp()) {
      const Token& t = Peek();
      if (t.kind == Tok::Ident && Text(t) == "depth") {
        Fail(Diag::BindingStage, RangeOf(t),
             "'result.depth' is a fragment-program result; vertex programs write "
             "result.position, result.color, result.fogcoord, result.pointsize or "
             "result.texcoord");
      }
      Token item =
          ExpectWord({"position", "color", "fogcoord", "pointsize", "texcoord"}, "vertex result");
      std::string_view w = Text(item);
      b.selector = RangeOf(item);
      if (w == "position") {
        b.result = ResultReg::Position;
      } else if (w == "color") {
        // <resultColBinding> ::= "color" <optFaceType> <optColorType>
        b.result = ResultReg::Color;
        std::string_view word;
        if (AcceptDotWord({"front", "back"}, &word))
          b.face = word == "back" ? Face::Back : Face::Front;
        if (AcceptDotWord({"primary", "secondary"}, &word)) b.secondary = word == "secondary";
        RejectUnknownSuffix({"front", "back", "primary", "secondary"}, "colour result");
      } else if (w == "fogcoord") {
        b.result = ResultReg::FogCoord;
      } else if (w == "pointsize") {
        b.result = ResultReg::PointSize;
      } else {
        b.result = ResultReg::TexCoord;
        ParseOptionalIndex(&b, "a texture coordinate number");
      }
    } else {
      const Token& t = Peek();
      if (t.kind == Tok::Ident && (Text(t) == "position" || Text(t) == "fogcoord" ||
                                   Text(t) == "pointsize" || Text(t) == "texcoord")) {
        Fail(Diag::BindingStage, RangeOf(t),
             fmt::format("'result.{}' is a vertex-program result; fragment programs write "
                         "result.color and result.depth",
                         Text(t)));
      }
      Token item = ExpectWord({"color", "depth"}, "fragment result");
      b.selector = RangeOf(item);
      if (Text(item) == "color") {
        b.result = ResultReg::FragColor;
        ParseOptionalIndex(&b, "a draw buffer number");
        if (PeekIs(Tok::Dot) && PeekIs(Tok::Ident, 1)) {
          std::string_view next = Text(Peek(1));
          if (next == "front" || next == "back" || next == "primary" || next == "secondary") {
            Fail(Diag::BindingStage, RangeOf(Peek(1)),
                 fmt::format("'result.color.{}' exists only in vertex programs; a fragment "
                             "program writes result.color",
                             next));
          }
        }
      } else {
        b.result = ResultReg::FragDepth;
      }
    }
    b.range = {start.begin, last_end_};
    return b;
  }

  // <progEnvParam(s)> / <progLocalParam(s)>:
  //   "program" "." ("env" | "local") "[" n ( ".." m )? "]"
  void ParseProgramItem(std::vector<Binding>* out, bool multiple) {
    Token start = Advance();
    ExpectDot("program");
    Token which = ExpectWord({"env", "local"}, "program parameter");
    Expect(Tok::LBracket, "'[' and a parameter number");
    Token first = ExpectInteger("a parameter number");
    int lo = ParseIntegerToken(first);
    int hi = lo;
    Token last = first;
    bool range = false;
    if (Accept(Tok::DotDot)) {
      last = ExpectInteger("the last parameter number of the range");
      hi = ParseIntegerToken(last);
      range = true;
    }
    Token close = Expect(Tok::RBracket, range ? "']'" : "']' or '..'");
    if (range && !multiple) {
      Fail(Diag::ParamArrayItem, {start.begin, close.end},
           fmt::format("'program.{}[{}..{}]' binds several vectors; it can only initialise a "
                       "PARAM array",
                       Text(which), lo, hi));
    }
    if (hi < lo) {
      Fail(Diag::BindingRowRange, RangeOf(last),
           fmt::format("parameter range [{}..{}] ends before it starts", lo, hi));
    }
    for (int i = lo; i <= hi; ++i) {
      Binding b;
      b.kind = Text(which) == "env" ? BindingKind::ProgramEnv : BindingKind::ProgramLocal;
      b.index = i;
      b.indexed = true;
      // A range is checked at its last number, a single parameter at its number.
      b.selector = (i == hi) ? RangeOf(last) : RangeOf(first);
      b.range = {start.begin, close.end};
      out->push_back(b);
    }
  }

  // <stateSingleItem> / <stateMultipleItem> ::= "state" "." ...
  void ParseStateItem(std::vector<Binding>* out, bool multiple) {
    Token start = Advance();
    ExpectDot("state");
    std::vector<std::string_view> items = {"material",  "light", "lightmodel",
                                           "lightprod", "fog",   "matrix"};
    if (vp()) {
      items.insert(items.end(), {"texgen", "clip", "point"});
    } else {
      items.insert(items.end(), {"texenv", "depth"});
    }
    const Token& t = Peek();
    if (t.kind == Tok::Ident) {
      std::string_view w = Text(t);
      if (vp() && (w == "texenv" || w == "depth")) {
        Fail(Diag::BindingStage, RangeOf(t),
             fmt::format("'state.{}' is available only in fragment programs", w));
      }
      if (fp() && (w == "texgen" || w == "clip" || w == "point")) {
        Fail(Diag::BindingStage, RangeOf(t),
             fmt::format("'state.{}' is available only in vertex programs", w));
      }
    }
    Token item = ExpectWordSlow(items, "state binding", Diag::BindingUnknown);
    std::string_view w = Text(item);
    Binding b;
    b.kind = BindingKind::State;
    b.selector = RangeOf(item);
    std::string_view word;
    if (w == "material") {
      // <stateMaterialItem> ::= "material" <optFaceType> "." <stateMatProperty>
      if (AcceptDotWord({"front", "back"}, &word))
        b.face = word == "back" ? Face::Back : Face::Front;
      ExpectDot("material");
      Token prop = ExpectWord({"ambient", "diffuse", "specular", "emission", "shininess"},
                              "material property");
      std::string_view p = Text(prop);
      b.state = p == "ambient"    ? StateItem::MaterialAmbient
                : p == "diffuse"  ? StateItem::MaterialDiffuse
                : p == "specular" ? StateItem::MaterialSpecular
                : p == "emission" ? StateItem::MaterialEmission
                                  : StateItem::MaterialShininess;
    } else if (w == "light") {
      // <stateLightItem> ::= "light" "[" <stateLightNumber> "]" "." <stateLightProperty>
      ParseRequiredIndex(&b, "a light number");
      ExpectDot("]");
      Token prop =
          ExpectWord({"ambient", "diffuse", "specular", "position", "attenuation", "spot", "half"},
                     "light property");
      std::string_view p = Text(prop);
      if (p == "spot") {
        ExpectDot("spot");
        ExpectWord({"direction"}, "spot property");
        b.state = StateItem::LightSpotDirection;
      } else {
        b.state = p == "ambient"    ? StateItem::LightAmbient
                  : p == "diffuse"  ? StateItem::LightDiffuse
                  : p == "specular" ? StateItem::LightSpecular
                  : p == "position" ? StateItem::LightPosition
                  : p == "half"     ? StateItem::LightHalf
                                    : StateItem::LightAttenuation;
      }
    } else if (w == "lightmodel") {
      // <stateLModProperty> ::= "." "ambient" | <optFaceType> "." "scenecolor"
      if (AcceptDotWord({"front", "back"}, &word)) {
        b.face = word == "back" ? Face::Back : Face::Front;
        ExpectDot(word);
        ExpectWord({"scenecolor"}, "light model property");
        b.state = StateItem::LightModelSceneColor;
      } else {
        ExpectDot("lightmodel");
        Token prop = ExpectWord({"ambient", "scenecolor"}, "light model property");
        b.state = Text(prop) == "ambient" ? StateItem::LightModelAmbient
                                          : StateItem::LightModelSceneColor;
      }
    } else if (w == "lightprod") {
      // <stateLightProdItem> ::= "lightprod" "[" n "]" <optFaceType> "." <stateLProdProperty>
      ParseRequiredIndex(&b, "a light number");
      if (AcceptDotWord({"front", "back"}, &word))
        b.face = word == "back" ? Face::Back : Face::Front;
      ExpectDot("]");
      Token prop = ExpectWord({"ambient", "diffuse", "specular"}, "light product property");
      std::string_view p = Text(prop);
      b.state = p == "ambient"   ? StateItem::LightProdAmbient
                : p == "diffuse" ? StateItem::LightProdDiffuse
                                 : StateItem::LightProdSpecular;
    } else if (w == "texgen") {
      // <stateTexGenItem> ::= "texgen" <optTexCoordNum> "." <stateTexGenType> "." <coord>
      ParseOptionalIndex(&b, "a texture unit number");
      ExpectDot("texgen");
      Token type = ExpectWord({"eye", "object"}, "texgen plane type");
      b.state = Text(type) == "eye" ? StateItem::TexGenEye : StateItem::TexGenObject;
      ExpectDot(Text(type));
      Token coord = ExpectWord({"s", "t", "r", "q"}, "texgen coordinate");
      std::string_view c = Text(coord);
      b.coord = c == "s" ? 0 : c == "t" ? 1 : c == "r" ? 2 : 3;
    } else if (w == "fog") {
      ExpectDot("fog");
      Token prop = ExpectWord({"color", "params"}, "fog property");
      b.state = Text(prop) == "color" ? StateItem::FogColor : StateItem::FogParams;
    } else if (w == "clip") {
      // <stateClipPlaneItem> ::= "clip" "[" n "]" "." "plane"
      ParseRequiredIndex(&b, "a clip plane number");
      ExpectDot("]");
      ExpectWord({"plane"}, "clip plane property");
      b.state = StateItem::ClipPlane;
    } else if (w == "point") {
      ExpectDot("point");
      Token prop = ExpectWord({"size", "attenuation"}, "point property");
      b.state = Text(prop) == "size" ? StateItem::PointSize : StateItem::PointAttenuation;
    } else if (w == "texenv") {
      // <stateTexEnvItem> ::= "texenv" <optLegacyTexUnitNum> "." "color"
      ParseOptionalIndex(&b, "a texture unit number");
      ExpectDot("texenv");
      ExpectWord({"color"}, "texture environment property");
      b.state = StateItem::TexEnvColor;
    } else if (w == "depth") {
      ExpectDot("depth");
      ExpectWord({"range"}, "depth property");
      b.state = StateItem::DepthRange;
    } else {
      ParseMatrixItem(start, b, out, multiple);
      return;
    }
    b.range = {start.begin, last_end_};
    out->push_back(b);
  }

  // <stateMatrixItem> ::= "matrix" "." <stateMatrixName> <stateOptMatModifier>
  // followed by ".row[n]" (single) or an optional ".row[a..b]" (multiple).
  void ParseMatrixItem(const Token& start, Binding b, std::vector<Binding>* out, bool multiple) {
    b.state = StateItem::MatrixRow;
    ExpectDot("matrix");
    Token name = ExpectWord({"modelview", "projection", "mvp", "texture", "palette", "program"},
                            "matrix name");
    std::string_view n = Text(name);
    b.selector = RangeOf(name);
    b.item = RangeOf(name);
    if (n == "modelview") {
      b.matrix = MatrixName::Modelview;
      ParseOptionalIndex(&b, "a modelview matrix number");
    } else if (n == "projection") {
      b.matrix = MatrixName::Projection;
    } else if (n == "mvp") {
      b.matrix = MatrixName::Mvp;
    } else if (n == "texture") {
      b.matrix = MatrixName::Texture;
      ParseOptionalIndex(&b, "a texture unit number");
    } else if (n == "palette") {
      b.matrix = MatrixName::Palette;
      ParseRequiredIndex(&b, "a palette matrix number");
    } else {
      b.matrix = MatrixName::Program;
      ParseRequiredIndex(&b, "a program matrix number");
    }
    std::string_view word;
    if (AcceptDotWord({"inverse", "transpose", "invtrans"}, &word)) {
      b.modifier = word == "inverse"     ? MatrixModifier::Inverse
                   : word == "transpose" ? MatrixModifier::Transpose
                                         : MatrixModifier::InvTrans;
    }
    if (PeekIs(Tok::Dot) && PeekIs(Tok::Ident, 1) && Text(Peek(1)) != "row" &&
        !LooksLikeSwizzle(Text(Peek(1)))) {
      const Token& bad = Peek(1);
      Fail(Diag::BindingUnknown, RangeOf(bad),
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
      Expect(Tok::LBracket, "'[' and a row number");
      Token first = ExpectInteger("a row number");
      lo = hi = ParseIntegerToken(first);
      lo_range = hi_range = RangeOf(first);
      if (Accept(Tok::DotDot)) {
        row_range = true;
        Token last = ExpectInteger("the last row number");
        hi = ParseIntegerToken(last);
        hi_range = RangeOf(last);
      }
      Expect(Tok::RBracket, row_range ? "']'" : "']' or '..'");
      // <stateMatrixRowNum> ::= <integer> from 0 to 3
      if (lo > 3) {
        Fail(Diag::BindingIndexRange, lo_range,
             fmt::format("matrix row {} does not exist; rows are numbered 0 to 3", lo));
      }
      if (hi > 3) {
        Fail(Diag::BindingIndexRange, hi_range,
             fmt::format("matrix row {} does not exist; rows are numbered 0 to 3", hi));
      }
      if (hi < lo) {
        Fail(Diag::BindingRowRange, hi_range,
             fmt::format("row range [{}..{}] ends before it starts", lo, hi));
      }
    }
    Range whole = {start.begin, last_end_};
    if (!multiple && (!has_rows || row_range)) {
      Fail(Diag::BindingMatrixNotSingle, RangeOf(start),
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
  }

  // ---- instructions --------------------------------------------------------------------

  void ParseInstruction() {
    Token op_token = Advance();
    std::string_view word = Text(op_token);
    Instruction inst;
    inst.opcode_range = RangeOf(op_token);
    std::string_view base = word;
    if (base.size() > 4 && base.substr(base.size() - 4) == "_SAT") {
      base.remove_suffix(4);
      inst.saturate = true;
    }
    if (!LookupOpcode(base, &inst.op)) {
      inst.saturate = false;
      ReportUnknownStatement(op_token);
    }
    const OpcodeInfo& info = GetOpcodeInfo(inst.op);
    if (inst.saturate && inst.op == Opcode::KIL) {
      Fail(Diag::SyntaxUnknownOpcode, RangeOf(op_token),
           "unknown instruction 'KIL_SAT': KIL writes no register, so it has no _SAT form");
    }
    if (!OpcodeInStage(inst.op, kind_)) {
      Fail(Diag::SyntaxOpcodeStage, RangeOf(op_token),
           fmt::format("'{}' is a {}-program instruction; it is not available in {} programs",
                       info.name, vp() ? "fragment" : "vertex", vp() ? "vertex" : "fragment"));
    }
    if (inst.saturate && vp()) {
      Fail(Diag::SyntaxSaturateVp, RangeOf(op_token),
           fmt::format("'{}': the _SAT suffix exists only in fragment programs; clamp with MIN "
                       "and MAX in a vertex program",
                       word));
    }
    switch (info.signature) {
      case OpSignature::Vector:
      case OpSignature::Binary:
      case OpSignature::Ternary: {
        inst.dst = ParseMaskedDstReg();
        int n = SourceCount(info.signature);
        for (int i = 0; i < n; ++i) {
          Expect(Tok::Comma, "',' and a source operand");
          inst.src[static_cast<size_t>(i)] = ParseSwizzleSrcReg(false);
        }
        inst.src_count = static_cast<uint8_t>(n);
        break;
      }
      case OpSignature::Scalar:
      case OpSignature::BinSc: {
        inst.dst = ParseMaskedDstReg();
        int n = SourceCount(info.signature);
        for (int i = 0; i < n; ++i) {
          Expect(Tok::Comma, "',' and a source operand");
          inst.src[static_cast<size_t>(i)] = ParseSwizzleSrcReg(true, info.name);
        }
        inst.src_count = static_cast<uint8_t>(n);
        break;
      }
      case OpSignature::Swz:
        inst.dst = ParseMaskedDstReg();
        Expect(Tok::Comma, "',' and a source operand");
        inst.src[0] = ParseSwzSource();
        inst.src_count = 1;
        break;
      case OpSignature::Arl:
        inst.dst = ParseMaskedAddrReg();
        Expect(Tok::Comma, "',' and a source operand");
        inst.src[0] = ParseSwizzleSrcReg(true, info.name);
        inst.src_count = 1;
        break;
      case OpSignature::Sample:
        inst.dst = ParseMaskedDstReg();
        Expect(Tok::Comma, "',' and the texture coordinate");
        inst.src[0] = ParseSwizzleSrcReg(false);
        inst.src_count = 1;
        Expect(Tok::Comma, "',' and a texture unit ('texture[n]')");
        ParseTexImageUnit(&inst);
        Expect(Tok::Comma, "',' and a texture target");
        ParseTexTarget(&inst);
        break;
      case OpSignature::Kil:
        inst.src[0] = ParseSwizzleSrcReg(false);
        inst.src_count = 1;
        if (PeekIs(Tok::Comma)) {
          Fail(Diag::SyntaxExpected, RangeOf(Peek()),
               "KIL takes exactly one source operand and no destination");
        }
        break;
    }
    inst.range = {op_token.begin, last_end_};
    program_->instructions.push_back(inst);
    ExpectSemicolon("instruction", info.name);
  }

  [[noreturn]] void ReportUnknownStatement(const Token& t) {
    std::string_view word = Text(t);
    std::vector<std::string_view> names;
    for (const OpcodeInfo& info : AllOpcodes()) {
      if (OpcodeInStage(info.op, kind_)) names.push_back(info.name);
    }
    for (std::string_view k : {"ATTRIB", "PARAM", "TEMP", "OUTPUT", "ALIAS", "OPTION", "END"}) {
      names.push_back(k);
    }
    if (vp()) names.push_back("ADDRESS");
    if (symbols_.count(word)) {
      Fail(Diag::SyntaxUnknownOpcode, RangeOf(t),
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
    Fail(Diag::SyntaxUnknownOpcode, RangeOf(t),
         fmt::format("unknown instruction '{}'{}", word, note));
  }

  // <maskedDstReg> ::= <dstReg> <optionalMask>
  // <dstReg> ::= <temporaryReg> | <vertexResultReg> / <fragmentResultReg>
  DstOperand ParseMaskedDstReg() {
    DstOperand dst;
    const Token& t = Peek();
    uint32_t begin = t.begin;
    if (PeekIdent("result")) {
      Binding b = ParseResultBinding();
      dst.var = AddImplicit(VarKind::Output, b);
    } else if (t.kind == Tok::Ident && IsBindingStart(t)) {
      Token start = Peek();
      std::string_view w = Text(start);
      Fail(Diag::OperandDstReadOnly, RangeOf(start),
           fmt::format("cannot write to a '{}' binding: destinations are temporaries and "
                       "result registers",
                       w));
    } else if (t.kind == Tok::Ident) {
      Token name = Advance();
      int var = ResolveName(name);
      VarKind k = program_->vars[static_cast<size_t>(var)].kind;
      if (k == VarKind::Attrib || k == VarKind::Param) {
        Fail(Diag::OperandDstReadOnly, RangeOf(name),
             fmt::format("cannot write to {} '{}': {} are read-only", KindName(k), Text(name),
                         k == VarKind::Attrib ? "attributes" : "parameters"));
      }
      if (k == VarKind::Address) {
        Fail(Diag::DeclWrongKind, RangeOf(name),
             fmt::format("address register '{}' can only be written by ARL", Text(name)));
      }
      if (PeekIs(Tok::LBracket)) {
        Fail(Diag::OperandNotArray, RangeOf(Peek()),
             fmt::format("'{}' is not an array and cannot be indexed", Text(name)));
      }
      dst.var = var;
    } else {
      FailExpected("a destination register");
    }
    dst.range = {begin, last_end_};
    // <optionalMask>
    if (PeekIs(Tok::Dot)) {
      Advance();
      Token mask = ExpectIdent("a write mask");
      dst.mask = ParseMask(mask);
    }
    return dst;
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
  void CheckComponentSets(const Token& t, int sets, std::string_view what) {
    if (sets == 3) {
      Fail(Diag::OperandSwizzleMix, RangeOf(t),
           fmt::format("{} '{}' mixes xyzw and rgba component names", what, Text(t)));
    }
    if (sets == 2 && vp()) {
      Fail(Diag::OperandRgbaVp, RangeOf(t),
           fmt::format("{} '{}' uses rgba component names, which only fragment programs "
                       "accept; use xyzw",
                       what, Text(t)));
    }
  }

  // <optionalMask>: components in order x, y, z, w, each at most once.
  uint8_t ParseMask(const Token& t) {
    std::string_view s = Text(t);
    int sets = 0;
    uint8_t mask = 0;
    int last = -1;
    bool ordered = true;
    for (char c : s) {
      int set = 0;
      int comp = ComponentOf(c, &set);
      if (comp < 0 || s.size() > 4) {
        Fail(Diag::OperandBadMask, RangeOf(t),
             fmt::format("'{}' is not a write mask; a mask lists components of {} in order", s,
                         fp() ? "xyzw or rgba" : "xyzw"));
      }
      sets |= set;
      if (comp <= last) ordered = false;
      last = comp;
      mask = static_cast<uint8_t>(mask | (1u << comp));
    }
    CheckComponentSets(t, sets, "write mask");
    if (!ordered) {
      Fail(Diag::OperandBadMask, RangeOf(t),
           fmt::format("write mask '{}' must list each component at most once, in the order "
                       "{}",
                       s, sets == 2 ? "r, g, b, a" : "x, y, z, w"));
    }
    return mask;
  }

  // <maskedAddrReg> ::= <addrReg> <addrWriteMask>; <addrWriteMask> ::= "." "x"
  DstOperand ParseMaskedAddrReg() {
    DstOperand dst;
    Token name = ExpectIdent("an address register");
    int var = ResolveName(name);
    if (program_->vars[static_cast<size_t>(var)].kind != VarKind::Address) {
      Fail(Diag::DeclWrongKind, RangeOf(name),
           fmt::format("ARL writes an address register, but '{}' is a {}", Text(name),
                       KindName(program_->vars[static_cast<size_t>(var)].kind)));
    }
    dst.var = var;
    dst.range = RangeOf(name);
    if (!PeekIs(Tok::Dot)) {
      Fail(Diag::OperandAddressComponent, {last_end_, last_end_},
           "ARL needs the write mask '.x' on its address register");
    }
    Advance();
    Token mask = ExpectIdent("the write mask 'x'");
    if (Text(mask) != "x") {
      Fail(
          Diag::OperandAddressComponent, RangeOf(mask),
          fmt::format("address register write mask '{}' is invalid; only '.x' exists", Text(mask)));
    }
    dst.mask = 1;
    return dst;
  }

  bool IsBindingStart(const Token& t) const {
    std::string_view w = Text(t);
    if (w == "state" || w == "program" || w == "result") return true;
    return w == (vp() ? "vertex" : "fragment");
  }

  int AddImplicit(VarKind kind, const Binding& b) {
    Variable var;
    var.kind = kind;
    var.decl = b.range;
    var.bindings.push_back(b);
    return AddVariable(std::move(var), nullptr);
  }

  // <srcReg> ::= <vertexAttribReg> | <temporaryReg> | <progParamReg>, with array access.
  SrcOperand ParseSrcReg(bool allow_constant) {
    SrcOperand src;
    const Token& t = Peek();
    if (t.kind == Tok::Ident) {
      std::string_view w = Text(t);
      if (IsAttribKeyword(t)) {
        src.var = AddImplicit(VarKind::Attrib, ParseAttribBinding());
        return src;
      }
      if (w == "state" || w == "program") {
        src.var = AddImplicit(VarKind::Param, ParseParamSingleItem(false));
        return src;
      }
      if (w == "result") {
        Token start = Peek();
        ParseResultBinding();
        Fail(Diag::OperandSrcWriteOnly, RangeOf(start),
             "cannot read a result register: results are write-only");
      }
      if ((w == "vertex" || w == "fragment") && !symbols_.count(w) && PeekIs(Tok::Dot, 1)) {
        Fail(Diag::BindingStage, RangeOf(t),
             fmt::format("'{}.*' bindings exist only in {} programs", w,
                         w == "vertex" ? "vertex" : "fragment"));
      }
      Token name = Advance();
      int var = ResolveName(name);
      const Variable& v = program_->vars[static_cast<size_t>(var)];
      src.var = var;
      if (v.kind == VarKind::Output) {
        Fail(Diag::OperandSrcWriteOnly, RangeOf(name),
             fmt::format("cannot read output '{}': results are write-only", Text(name)));
      }
      if (v.kind == VarKind::Address) {
        Fail(Diag::DeclWrongKind, RangeOf(name),
             fmt::format("address register '{}' can only be used to index a PARAM array, as in "
                         "'array[{}.x]'",
                         Text(name), Text(name)));
      }
      if (PeekIs(Tok::LBracket)) {
        if (!v.is_array) {
          Fail(Diag::OperandNotArray, RangeOf(Peek()),
               fmt::format("'{}' is not a PARAM array and cannot be indexed", Text(name)));
        }
        ParseArrayMember(&src, v, name);
      } else if (v.is_array) {
        Fail(
            Diag::OperandArrayNoIndex, RangeOf(name),
            fmt::format("PARAM array '{}' must be indexed, as in '{}[0]'", Text(name), Text(name)));
      }
      return src;
    }
    if (allow_constant && (t.kind == Tok::Minus || t.kind == Tok::Plus) &&
        (PeekIs(Tok::Integer, 1) || PeekIs(Tok::Float, 1))) {
      Fail(Diag::OperandNegatedConstant, RangeOf(t),
           "an inline scalar constant takes no sign of its own; the operand has one sign, "
           "before the constant");
    }
    if (allow_constant &&
        (t.kind == Tok::Integer || t.kind == Tok::Float || t.kind == Tok::LBrace)) {
      src.var = AddImplicit(VarKind::Param, ParseParamSingleItem(false));
      return src;
    }
    FailExpected("a source operand");
  }

  // <progParamArrayMem> ::= <progParamArrayAbs> | <progParamArrayRel>
  void ParseArrayMember(SrcOperand* src, const Variable& v, const Token& name) {
    Advance();  // '['
    src->indexed = true;
    if (PeekIs(Tok::Integer)) {
      Token n = Advance();
      src->index = ParseIntegerToken(n);
      if (static_cast<size_t>(src->index) >= v.bindings.size()) {
        Fail(Diag::OperandIndexRange, RangeOf(n),
             fmt::format("index {} is out of bounds for array '{}' of {} element{}", src->index,
                         Text(name), v.bindings.size(), v.bindings.size() == 1 ? "" : "s"));
      }
    } else if (PeekIs(Tok::Ident)) {
      // <progParamArrayRel> ::= <addrReg> <addrComponent> <addrRegRelOffset>
      Token addr = Advance();
      if (fp()) {
        Fail(Diag::OperandRelativeFp, RangeOf(addr),
             "relative addressing exists only in vertex programs; fragment programs index "
             "arrays with constants");
      }
      int var = ResolveName(addr);
      if (program_->vars[static_cast<size_t>(var)].kind != VarKind::Address) {
        Fail(Diag::DeclWrongKind, RangeOf(addr),
             fmt::format("'{}' is a {}, not an address register; relative indices use an "
                         "ADDRESS register",
                         Text(addr), KindName(program_->vars[static_cast<size_t>(var)].kind)));
      }
      src->relative = true;
      src->address_var = var;
      if (!PeekIs(Tok::Dot)) {
        Fail(Diag::OperandAddressComponent, {last_end_, last_end_},
             fmt::format("address register '{}' needs the component '.x'", Text(addr)));
      }
      Advance();
      Token comp = ExpectIdent("the address component 'x'");
      if (Text(comp) != "x") {
        Fail(Diag::OperandAddressComponent, RangeOf(comp),
             fmt::format("address component '{}' is invalid; only '.x' exists", Text(comp)));
      }
      // <addrRegRelOffset> ::= "" | "+" <addrRegPosOffset> | "-" <addrRegNegOffset>
      if (PeekIs(Tok::Plus) || PeekIs(Tok::Minus)) {
        bool negative = Text(Advance()) == "-";
        Token n = ExpectInteger("an offset");
        int offset = ParseIntegerToken(n);
        if ((negative && offset > 64) || (!negative && offset > 63)) {
          Fail(Diag::OperandOffsetRange, RangeOf(n),
               fmt::format("relative offset {}{} is out of range; offsets go from -64 to +63",
                           negative ? "-" : "+", offset));
        }
        src->index = negative ? -offset : offset;
      }
    } else {
      FailExpected("an array index");
    }
    Expect(Tok::RBracket, "']' after the array index");
  }

  // <swizzleSrcReg> / <vectorSrcReg> ::= <optionalSign> <srcReg> <swizzleSuffix>
  // <scalarSrcReg> ::= <optionalSign> <srcReg> <scalarSuffix>
  SrcOperand ParseSwizzleSrcReg(bool scalar, std::string_view opname = {}) {
    uint32_t begin = Peek().begin;
    bool negate = false;
    if (PeekIs(Tok::Minus) || PeekIs(Tok::Plus)) negate = Text(Advance()) == "-";
    SrcOperand src = ParseSrcReg(/*allow_constant=*/true);
    src.negate = negate;
    src.range = {begin, last_end_};
    if (PeekIs(Tok::Dot)) {
      Advance();
      Token swz = ExpectIdent("a swizzle");
      ParseSwizzle(swz, scalar, opname, &src);
    } else if (scalar) {
      Fail(Diag::OperandScalarRequired, src.range,
           fmt::format(
               "'{}' takes a scalar operand: select one component, as in '{}.x'", opname,
               std::string_view(text_).substr(src.range.begin, src.range.end - src.range.begin)));
    }
    return src;
  }

  void ParseSwizzle(const Token& t, bool scalar, std::string_view opname, SrcOperand* src) {
    std::string_view s = Text(t);
    int sets = 0;
    std::array<Swz, 4> swz{};
    for (size_t i = 0; i < s.size() && i < 4; ++i) {
      int set = 0;
      int comp = ComponentOf(s[i], &set);
      if (comp < 0) {
        Fail(Diag::OperandBadSwizzle, RangeOf(t),
             fmt::format("'{}' is not a swizzle: use one or four of {}", s,
                         fp() ? "x, y, z, w (or r, g, b, a)" : "x, y, z, w"));
      }
      sets |= set;
      swz[i] = static_cast<Swz>(comp);
    }
    if (s.size() != 1 && s.size() != 4) {
      Fail(Diag::OperandBadSwizzle, RangeOf(t),
           fmt::format("swizzle '{}' has {} components; a swizzle selects one or four", s,
                       s.size()));
    }
    CheckComponentSets(t, sets, "swizzle");
    if (scalar && s.size() != 1) {
      Fail(Diag::OperandScalarRequired, RangeOf(t),
           fmt::format("'{}' takes a scalar operand: '.{}' selects four components; select one",
                       opname, s));
    }
    if (s.size() == 1) {
      src->swizzle = {swz[0], swz[0], swz[0], swz[0]};
    } else {
      src->swizzle = swz;
    }
  }

  // SWZ: <srcReg> "," <extendedSwizzle> (no sign, no suffix on the register)
  SrcOperand ParseSwzSource() {
    uint32_t begin = Peek().begin;
    if (PeekIs(Tok::Minus) || PeekIs(Tok::Plus)) {
      Fail(Diag::OperandExtSwizzle, RangeOf(Peek()),
           "SWZ takes a register without sign; negate components in the extended swizzle "
           "('-x')");
    }
    SrcOperand src = ParseSrcReg(/*allow_constant=*/true);
    src.range = {begin, last_end_};
    if (PeekIs(Tok::Dot)) {
      Fail(Diag::OperandExtSwizzle, RangeOf(Peek()),
           "SWZ takes a register without suffix; the swizzle is the four selectors that "
           "follow");
    }
    // <extendedSwizzle> ::= <extSwizComp> "," <extSwizComp> "," <extSwizComp> "," <extSwizComp>
    int sets = 0;
    for (int i = 0; i < 4; ++i) {
      if (!PeekIs(Tok::Comma)) {
        Fail(Diag::OperandExtSwizzle,
             PeekIs(Tok::Semicolon) ? Range{last_end_, last_end_} : RangeOf(Peek()),
             fmt::format("SWZ needs four selectors (0, 1, or a component, each with an "
                         "optional sign); found {}",
                         i));
      }
      Advance();  // ','
      bool negative = false;
      if (PeekIs(Tok::Minus) || PeekIs(Tok::Plus)) negative = Text(Advance()) == "-";
      const Token& sel = Peek();
      std::string_view s = Text(sel);
      Swz value;
      if (sel.kind == Tok::Integer && (s == "0" || s == "1")) {
        value = s == "0" ? Swz::Zero : Swz::One;
      } else if (sel.kind == Tok::Ident && s.size() == 1) {
        int set = 0;
        int comp = ComponentOf(s[0], &set);
        if (comp < 0) {
          Fail(Diag::OperandExtSwizzle, RangeOf(sel),
               fmt::format("'{}' is not an extended swizzle selector; use 0, 1 or one of {}", s,
                           fp() ? "x, y, z, w, r, g, b, a" : "x, y, z, w"));
        }
        if (set == 2 && vp()) {
          Fail(
              Diag::OperandRgbaVp, RangeOf(sel),
              fmt::format("selector '{}' is an rgba name, which only fragment programs accept", s));
        }
        if ((sets | set) == 3) {
          Fail(Diag::OperandSwizzleMix, RangeOf(sel),
               "extended swizzle mixes xyzw and rgba component names");
        }
        sets |= set;
        value = static_cast<Swz>(comp);
      } else {
        Fail(Diag::OperandExtSwizzle, RangeOf(sel),
             fmt::format("{} is not an extended swizzle selector; use 0, 1 or a single "
                         "component name",
                         Describe(sel)));
      }
      Advance();
      src.swizzle[static_cast<size_t>(i)] = value;
      src.component_negate[static_cast<size_t>(i)] = negative;
    }
    if (PeekIs(Tok::Comma)) {
      Fail(Diag::OperandExtSwizzle, RangeOf(Peek()), "SWZ takes exactly four selectors");
    }
    return src;
  }

  // <texImageUnit> ::= "texture" <optTexImageUnitNum>
  void ParseTexImageUnit(Instruction* inst) {
    if (!PeekIdent("texture")) FailExpected("a texture unit ('texture' or 'texture[n]')");
    Token kw = Advance();
    inst->unit_range = RangeOf(kw);
    inst->tex_unit = 0;
    if (PeekIs(Tok::LBracket)) {
      Token n = ParseBracketIndex("a texture image unit number");
      inst->tex_unit = ParseIntegerToken(n);
      inst->unit_range = RangeOf(n);
    }
  }

  // <texTarget> ::= "1D" | "2D" | "3D" | "CUBE" | "RECT" (| "SHADOW1D" | "SHADOW2D" |
  //                 "SHADOWRECT" with ARB_fragment_program_shadow)
  void ParseTexTarget(Instruction* inst) {
    static const std::pair<std::string_view, TexTarget> kTargets[] = {
        {"1D", TexTarget::Tex1D},          {"2D", TexTarget::Tex2D},
        {"3D", TexTarget::Tex3D},          {"CUBE", TexTarget::Cube},
        {"RECT", TexTarget::Rect},         {"SHADOW1D", TexTarget::Shadow1D},
        {"SHADOW2D", TexTarget::Shadow2D}, {"SHADOWRECT", TexTarget::ShadowRect}};
    const Token& t = Peek();
    if (t.kind == Tok::Ident) {
      for (const auto& [name, target] : kTargets) {
        if (Text(t) == name) {
          inst->target = target;
          inst->target_range = RangeOf(Advance());
          return;
        }
      }
    }
    std::vector<std::string_view> names;
    for (const auto& [name, target] : kTargets) names.push_back(name);
    std::string hint = t.kind == Tok::Ident || t.kind == Tok::Integer ? ClosestMatch(Text(t), names)
                                                                      : std::string();
    Fail(Diag::TextureUnknownTarget, RangeOf(t),
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
  std::unique_ptr<Program> program_;
  std::unordered_map<std::string, Symbol, StringHash, std::equal_to<>> symbols_;
};

}  // namespace

bool IsReservedWord(std::string_view word, ProgramKind kind) {
  const auto& keywords = kind == ProgramKind::Vertex ? kVpKeywords : kFpKeywords;
  for (std::string_view k : keywords) {
    if (k == word) return true;
  }
  std::string_view base = word;
  bool sat = base.size() > 4 && base.substr(base.size() - 4) == "_SAT";
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
