// glslang's info log -> arbiter diagnostics. glslang 12 writes
//   ERROR: <name>:<line>: '<token>' : <text>
//   ERROR: Linking <stage> stage: <text>
// (continuation lines indented), without columns: the column comes from the quoted token,
// found on its line.
#include "info_log.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <string>
#include <string_view>

#include "conditionals.h"
#include "diag.h"
#include "prepare.h"
#include "scan.h"
#include "source_text.h"
#include "syntax_error.h"

namespace arbiter::glsl {
namespace {

using compiler::SourceFile;

// glslang's bison parser: YYMAXDEPTH, the default.
constexpr int kParserStackDepth = 10000;

// Which code a glslang message gets: the first rule whose text occurs in the message.
struct MessageRule {
  std::string_view needle;
  Diag diag;
};

constexpr MessageRule kCompileRules[] = {
    // The shader's own words, which may hold any of the needles below.
    {"'#error' :", Diag::ErrorDirective},
    {"extension not supported", Diag::ExtensionUnsupported},
    // bison's "memory exhausted": its stack of YYMAXDEPTH (10000) entries overflowed.
    {"memory exhausted", Diag::NestingTooDeep},
    {"syntax error", Diag::SyntaxError},
    {"cannot be bool", Diag::VaryingType},
    {"must be qualified as flat", Diag::VaryingType},
    {"undeclared identifier", Diag::Undeclared},
    {"redefinition", Diag::Redefinition},
    {"eserved word", Diag::ReservedWord},
    {"reserved for future use", Diag::ReservedWord},
    {"cannot convert", Diag::TypeMismatch},
    {"wrong operand types", Diag::TypeMismatch},
    {"convert no return value", Diag::TypeMismatch},
    {"index out of range", Diag::ArraySize},
    {"no matching overloaded function", Diag::NoMatchingFunction},
    {"constructor", Diag::Constructor},
    {"l-value", Diag::LValue},
    {"not supported for this version", Diag::Version},
    {"#version", Diag::Version},
    {"version", Diag::Version},
    {"qualifier", Diag::Qualifier},
    {"array", Diag::ArraySize},
    {"#", Diag::Preprocessor},
    {"macro", Diag::Preprocessor},
    {"preprocessor", Diag::Preprocessor},
};

constexpr MessageRule kLinkRules[] = {
    {"Missing entry point", Diag::LinkMissingMain},
    {"No function definition", Diag::LinkMissingFunction},
    {"Recursion detected", Diag::LinkRecursion},
    {"recursion", Diag::LinkRecursion},
    {"gl_FragColor and gl_FragData", Diag::LinkFragColorAndData},
};

std::string_view Trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

// glslang spells types with storage prefixes and stray blanks (' const int', ' temp float').
std::string CleanText(std::string_view text) {
  std::string out(Trim(text));
  // Only opening quotes are followed by a blank: " ' temp float'" -> " 'float'".
  for (std::string_view noise : {" ' temp ", " ' const ", " ' uniform ", " ' in ", " ' "}) {
    std::string replacement = noise == " ' const " ? " 'const " : " '";
    for (size_t at = out.find(noise); at != std::string::npos;
         at = out.find(noise, at + replacement.size())) {
      out.replace(at, noise.size(), replacement);
    }
  }
  std::string collapsed;
  for (char c : out) {
    if (c == ' ' && !collapsed.empty() && collapsed.back() == ' ') continue;
    collapsed += c;
  }
  return collapsed;
}

// The byte range of `token` on 1-based `line` of `file` (a whole-word match for identifiers);
// the start of the line when it is not there.
compiler::Range FindOnLine(const SourceFile& file, uint32_t line, std::string_view token) {
  if (line < 1 || line > file.line_count()) return {0, 0};
  uint32_t start = file.LineStart(line);
  std::string_view text = file.LineText(line);
  bool word = !token.empty() && IsIdentChar(token.front()) && IsIdentChar(token.back());
  for (size_t at = token.empty() ? std::string_view::npos : text.find(token);
       at != std::string_view::npos; at = text.find(token, at + 1)) {
    bool before_ok = at == 0 || !IsIdentChar(text[at - 1]);
    bool after_ok = at + token.size() >= text.size() || !IsIdentChar(text[at + token.size()]);
    if (!word || (before_ok && after_ok)) {
      auto begin = static_cast<uint32_t>(start + at);
      return {begin, static_cast<uint32_t>(begin + token.size())};
    }
  }
  return {start, start};
}

// The 'f' of a float literal like 1.0f on `line` (glslang names it "floating-point suffix").
compiler::Range FindFloatSuffix(const SourceFile& file, uint32_t line) {
  if (line < 1 || line > file.line_count()) return {0, 0};
  uint32_t start = file.LineStart(line);
  std::string_view text = file.LineText(line);
  for (size_t i = 1; i < text.size(); ++i) {
    bool suffix = text[i] == 'f' || text[i] == 'F';
    bool after_number = std::isdigit(static_cast<unsigned char>(text[i - 1])) || text[i - 1] == '.';
    bool ends = i + 1 >= text.size() || !IsIdentChar(text[i + 1]);
    size_t j = i;
    while (j > 0 && (IsIdentChar(text[j - 1]) || text[j - 1] == '.')) --j;
    bool starts_numeric = std::isdigit(static_cast<unsigned char>(text[j])) || text[j] == '.';
    if (suffix && after_number && ends && starts_numeric) {
      return {static_cast<uint32_t>(start + i), static_cast<uint32_t>(start + i + 1)};
    }
  }
  return {start, start};
}

// Where ( [ { first nest deepest in `file`, comments skipped: the place a parser stack
// overflow is about (glslang names the line only, and bison's depth is not the bracket depth).
compiler::Range DeepestNesting(const SourceFile& file) {
  std::string_view text = file.text();
  size_t depth = 0;
  size_t deepest = 0;
  size_t where = 0;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text.compare(i, 2, "//") == 0) {
      i = std::min(text.find('\n', i), text.size());
    } else if (text.compare(i, 2, "/*") == 0) {
      size_t end = text.find("*/", i + 2);
      i = end == std::string_view::npos ? text.size() : end + 1;
    } else if (text[i] == '(' || text[i] == '[' || text[i] == '{') {
      if (++depth > deepest) {
        deepest = depth;
        where = i;
      }
    } else if ((text[i] == ')' || text[i] == ']' || text[i] == '}') && depth > 0) {
      --depth;
    }
  }
  return {static_cast<uint32_t>(where), static_cast<uint32_t>(deepest > 0 ? where + 1 : where)};
}

// The first whole-word occurrence of `token` in any source (for link messages).
bool FindAnywhere(const std::vector<const SourceFile*>& sources, std::string_view token,
                  const SourceFile** file, compiler::Range* range) {
  for (const SourceFile* f : sources) {
    for (uint32_t line = 1; line <= f->line_count(); ++line) {
      compiler::Range r = FindOnLine(*f, line, token);
      if (r.end > r.begin) {
        *file = f;
        *range = r;
        return true;
      }
    }
  }
  return false;
}

// The backslash that ends `line` of `file`, where glslang reports a line continuation; the
// start of the line when there is none.
compiler::Range BackslashAtEnd(const SourceFile& file, uint32_t line) {
  if (line < 1 || line > file.line_count()) return {0, 0};
  const uint32_t start = file.LineStart(line);
  std::string_view text = file.LineText(line);
  while (!text.empty() && text.back() == '\r') text.remove_suffix(1);
  if (text.empty() || text.back() != '\\') return {start, start};
  const auto at = static_cast<uint32_t>(start + text.size() - 1);
  return {at, at + 1};
}

// Whether `offset` of `file` is in a conditional group known to be skipped (conditionals.h).
bool InSkippedGroup(const InfoLogContext& ctx, const SourceFile* file, uint32_t offset) {
  auto it = std::find(ctx.sources.begin(), ctx.sources.end(), file);
  if (it == ctx.sources.end()) return false;  // the preamble or an included file
  std::vector<std::string_view> texts;
  for (const SourceFile* source : ctx.sources) texts.push_back(source->text());
  const ShaderReach reach(ctx.prepared != nullptr ? ctx.prepared->preamble : "", texts);
  return reach.At(static_cast<size_t>(it - ctx.sources.begin()), offset) == Reach::Skipped;
}

// glslang 12 rejects a line continuation (backslash-newline) before GLSL 4.20, and arbiter
// keeps that error, at the backslash: 1.10 and 1.20 have none (docs/glsl-disagreements.md
// A11: 3.1's character set has no backslash). Inside a group known to be skipped it is a
// warning of its own code: 3.3's conditionals "operate as is standard for C++
// preprocessors", which do not process a skipped group's text, and every driver accepts it
// there (piglit's if-statement-in-macro-in-false-ifdef.vert). In a group whose condition
// arbiter cannot evaluate, the error stands. Returns false for the warning: glslang joined
// the lines and went on, so its result stands.
bool EmitLineContinuation(const InfoLogContext& ctx, const SourceFile* file, uint32_t line,
                          const std::string& message, compiler::DiagnosticSink* sink) {
  const compiler::Range range = BackslashAtEnd(*file, line);
  if (!InSkippedGroup(ctx, file, range.begin)) {
    sink->Report(Info(Diag::Version), file, range, message + " ('line continuation')");
    return true;
  }
  sink->Report(Info(Diag::SkippedLineContinuation), file, range,
               fmt::format("line continuation (a backslash at the end of a line) in a "
                           "conditional group the preprocessor skips: {} has none (section "
                           "3.1 has no backslash), but a skipped group is not compiled, and "
                           "every driver accepts it",
                           ctx.version == 120 ? "GLSL 1.20" : "GLSL 1.10"));
  return false;
}

Diag Classify(std::string_view text, bool link, bool warning) {
  if (link) {
    for (const MessageRule& rule : kLinkRules) {
      if (text.find(rule.needle) != std::string_view::npos) return rule.diag;
    }
    return Diag::LinkError;
  }
  if (warning) {
    // GLSL 1.10 3.6 reserves identifiers (and 3.3 macro names) containing "__"; glslang
    // only warns (later versions relaxed it).
    if (text.find("consecutive underscores") != std::string_view::npos) return Diag::ReservedWord;
    if (text.find("extension not supported") != std::string_view::npos) {
      return Diag::ExtensionUnsupported;
    }
    return Diag::CompileWarning;
  }
  for (const MessageRule& rule : kCompileRules) {
    if (text.find(rule.needle) != std::string_view::npos) return rule.diag;
  }
  return Diag::CompileError;
}

struct Message {
  bool warning = false;
  std::string body;  // after "ERROR: ", continuation lines appended
};

// glslang errors that GLSL 1.10 does not make: dropped, or turned into a warning where
// 1.10 leaves the behaviour undefined. glslang recovers from each of them without further
// errors and builds the AST the 1.10 text describes, so the strictness layer still runs.
struct Relaxation {
  std::string_view needle;
  bool link;  // a message of the link step
  bool vertex_only;
  Diag warning;              // CompileError: dropped without a message
  int only_version = 0;      // 110: an error of 1.20 that 1.10 does not make; 0: both
  bool object_only = false;  // dropped for a shader object, kept for a program
};

constexpr Relaxation kRelaxations[] = {
    // 8.7: vertex shaders have texture2DLod, ..., shadow2DProjLod without any extension;
    // glslang 12 asks for GL_ARB_shader_texture_lod (only dropped for the Lod built-ins).
    {"required extension not requested: GL_ARB_shader_texture_lod", false, true,
     Diag::CompileError},
    // 4.1.8: "Member types must be ... defined in-place by embedding another struct
    // definition"; glslang 12 follows later versions. It still parses the definition and
    // scopes its name at the level of the outer struct, as 4.1.8 says.
    // 1.20 4.1.8 forbids them: "Embedded structures are not supported."
    {"cannot nest a structure definition inside a structure", false, false, Diag::CompileError,
     110},
    // 5.8 and 5.7: entire structures are l-values, can be compared and initialize a
    // structure variable (4.1.8), array fields or not;
    // glslang applies 1.20's rule for structures with array fields. Whole arrays as
    // operands are rejected by strict_expressions.cpp from the AST instead.
    {"'array assignment' : not supported for this version", false, false, Diag::CompileError},
    {"'array comparison' : not supported for this version", false, false, Diag::CompileError},
    {"'array initializer' : not supported for this version", false, false, Diag::CompileError},
    // 5.5, 5.6: "Behavior is undefined if the index is greater than or equal to the size of
    // the vector" (likewise for matrix columns): not an error (4.1.9 makes it one for arrays
    // only). glslang clamps the index and goes on.
    // 1.20 5.5, 5.6 make a constant index out of range an error ("is illegal").
    {"vector index out of range", false, false, Diag::IndexOutOfRange, 110},
    {"matrix index out of range", false, false, Diag::IndexOutOfRange, 110},
    // 4.3.2 and 5.9: a comma of constant operands is constant (1.20 4.3.3 too); glslang 12
    // folds no comma (GLSL 4.x excludes the sequence operator). It keeps the local const
    // read-only, with its initializer, and goes on; strict_qualifiers.cpp judges the operands.
    {"'non-constant initializer' : not supported for this version", false, false,
     Diag::CompileError},
    // 7.2: only assigning both gl_FragColor and gl_FragData is an error; glslang counts any
    // use. strict_builtins.cpp checks the static writes instead.
    {"Cannot use both gl_FragColor and gl_FragData", true, false, Diag::CompileError},
    // A shader object (glCompileShader) may lack main() and call functions that another
    // object of the program defines: errors of the program only.
    {"Missing entry point", true, false, Diag::CompileError, 0, true},
    {"No function definition (body) found", true, false, Diag::CompileError, 0, true},
};

// The relaxation that applies to an error, if any.
const Relaxation* Relaxed(std::string_view body, const InfoLogContext& ctx, bool link) {
  for (const Relaxation& r : kRelaxations) {
    if (r.link != link || body.find(r.needle) == std::string_view::npos) continue;
    if (r.only_version != 0 && r.only_version != ctx.version) continue;
    if (r.object_only && ctx.program) continue;
    if (r.vertex_only &&
        (ctx.stage != Stage::Vertex || body.find("Lod'") == std::string_view::npos)) {
      continue;
    }
    return &r;
  }
  return nullptr;
}

// Returns false when the message was dropped by a relaxation.
bool Emit(const Message& m, const InfoLogContext& ctx, bool link, compiler::DiagnosticSink* sink) {
  const std::vector<const SourceFile*>& sources = ctx.sources;
  // Deprecations of 1.30 come from parsing an EXT_gpu_shader4 shader as 1.30 (prepare.h):
  // nothing of 1.10 or 1.20 is deprecated.
  if (m.warning && m.body.find("deprecated in version") != std::string::npos) return true;
  // glslang only warns about a return value of another type; 1.10 has no implicit
  // conversions (4.1.10), and 1.20's are "done only as indicated by other sections" (4.1.10),
  // which 6.1 and 6.4 do not do for return.
  constexpr std::string_view kReturnConversion = "type conversion on return values";
  if (m.warning && m.body.find(kReturnConversion) != std::string::npos) {
    Message error = m;
    error.warning = false;
    error.body.replace(error.body.find(kReturnConversion), error.body.size(),
                       "the returned value's type is not the function's return type, and "
                       "GLSL 1.10 and 1.20 convert no return value (section 4.1.10)");
    return Emit(error, ctx, link, sink);
  }
  const Relaxation* relaxed = m.warning ? nullptr : Relaxed(m.body, ctx, link);
  if (relaxed != nullptr && relaxed->warning == Diag::CompileError) return false;
  // glslang's messages name the words source_text.cpp renamed as it saw them.
  std::string restored = ctx.prepared != nullptr ? RestoreSpelling(m.body, ctx.prepared->renames)
                                                 : RestoreSpelling(m.body);
  std::string_view body = restored;
  // Summary lines ("3 compilation errors.  No code generated.") repeat what came before.
  if (body.find("compilation errors") != std::string_view::npos ||
      body.find("compilation error.") != std::string_view::npos) {
    return true;
  }
  // "<string>:<line>: " where <string> is the source string number (0 for the first file).
  const SourceFile* file = sources.front();
  uint32_t line = 0;
  {
    size_t colon = body.find(':');
    size_t colon2 = colon == std::string_view::npos ? colon : body.find(':', colon + 1);
    auto all_digits = [](std::string_view d) {
      return !d.empty() && std::all_of(d.begin(), d.end(), [](char c) {
        return std::isdigit(static_cast<unsigned char>(c));
      });
    };
    // "-1:<line>:": the preamble (prepare.h): the --preamble file after arbiter's own lines.
    if (colon2 != std::string_view::npos && body.substr(0, colon) == "-1" &&
        all_digits(body.substr(colon + 1, colon2 - colon - 1))) {
      auto preamble_line = static_cast<uint32_t>(
          std::stoul(std::string(body.substr(colon + 1, colon2 - colon - 1))));
      const PreparedShader* prepared = ctx.prepared;
      if (prepared != nullptr && prepared->preamble_file != nullptr &&
          preamble_line > prepared->preamble_generated_lines) {
        file = prepared->preamble_file;
        line = preamble_line - prepared->preamble_generated_lines;
      }
      body = Trim(body.substr(colon2 + 1));
    } else if (colon2 != std::string_view::npos && ctx.prepared != nullptr &&
               IncludedFile(*ctx.prepared, body.substr(0, colon)) != nullptr &&
               all_digits(body.substr(colon + 1, colon2 - colon - 1))) {
      // "<path>:<line>:": a file #include read.
      file = IncludedFile(*ctx.prepared, body.substr(0, colon));
      line = static_cast<uint32_t>(
          std::stoul(std::string(body.substr(colon + 1, colon2 - colon - 1))));
      body = Trim(body.substr(colon2 + 1));
    } else if (colon2 != std::string_view::npos && all_digits(body.substr(0, colon)) &&
               all_digits(body.substr(colon + 1, colon2 - colon - 1))) {
      size_t string = std::stoul(std::string(body.substr(0, colon)));
      if (string < sources.size()) file = sources[string];
      line = static_cast<uint32_t>(
          std::stoul(std::string(body.substr(colon + 1, colon2 - colon - 1))));
      body = Trim(body.substr(colon2 + 1));
    }
  }
  constexpr std::string_view kLinking = "Linking ";
  if (body.substr(0, kLinking.size()) == kLinking) {
    size_t colon = body.find(':');
    if (colon != std::string_view::npos) body = Trim(body.substr(colon + 1));
  }
  // "'token' : text"
  std::string token;
  std::string text(body);
  if (body.size() > 2 && body.front() == '\'') {
    size_t close = body.find("' :");
    if (close != std::string_view::npos) {
      token = std::string(body.substr(1, close - 1));
      text = std::string(Trim(body.substr(close + 3)));
    }
  }
  // A name glslang could not take was shortened (PrepareForGlslang): the line has the real one.
  if (token.rfind(kLongNamePrefix, 0) == 0 && line > 0 && file != nullptr &&
      static_cast<uint32_t>(line) <= file->line_count()) {
    const std::vector<Token> words = Tokenize(file->LineText(static_cast<uint32_t>(line)));
    for (const Token& w : words) {
      if (w.kind == Token::Identifier && w.text.size() > 1000) {
        token = std::string(w.text);
        break;
      }
    }
  }
  if (!link && !m.warning && token == "line continuation" && line > 0) {
    return EmitLineContinuation(ctx, file, line, CleanText(text), sink);
  }
  Diag diag = relaxed != nullptr ? relaxed->warning : Classify(body, link, m.warning);
  // glslang's warning about "__" names is reported as an error by the strictness layer.
  if (m.warning && diag == Diag::ReservedWord) return true;
  std::string message = CleanText(text);
  // #include is glslang's under its own extension's name; arbiter's is the ARB one.
  constexpr std::string_view kGoogleInclude =
      "required extension not requested: GL_GOOGLE_include_directive";
  constexpr std::string_view kNotFound = "Could not process include directive for header name: ";
  if (message.find(kGoogleInclude) != std::string::npos) {
    message = "#include needs '#extension GL_ARB_shading_language_include : enable' (or require)";
  } else if (message.compare(0, kNotFound.size(), kNotFound) == 0) {
    const std::string header = message.substr(kNotFound.size());
    const std::string* reason = nullptr;
    if (ctx.prepared != nullptr) {
      auto failure = ctx.prepared->include_failures.find(header);
      if (failure != ctx.prepared->include_failures.end()) reason = &failure->second;
    }
    if (reason != nullptr) {
      message = *reason;
    } else {
      message = fmt::format(
          "cannot find the #include file '{}' (looked next to the including file, then in each "
          "-I directory)",
          header);
    }
  }
  // Diagnostics start in lower case (docs/design/style.md E4); keep acronyms ("GLSL") as they are.
  if (message.size() > 1 && std::isupper(static_cast<unsigned char>(message[0])) &&
      std::islower(static_cast<unsigned char>(message[1]))) {
    message[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(message[0])));
  }
  if (diag == Diag::NestingTooDeep) {
    message = fmt::format(
        "nested too deeply: the parser's stack ({} entries) overflowed; GLSL 1.10 sets no "
        "limit, but no front end parses this: split the expression or statement",
        kParserStackDepth);
  } else if (relaxed != nullptr) {
    message += fmt::format(
        "; {} leaves such an access undefined (sections 5.5 and 5.6), it is "
        "no error",
        ctx.version == 120 ? "GLSL 1.20" : "GLSL 1.10");
  } else if (token.size() > 64) {
    message += fmt::format(" ('{}...', {} characters)", token.substr(0, 32), token.size());
  } else if (!token.empty()) {
    message += fmt::format(" ('{}')", token);
  }

  // "extension not supported: NAME" quotes '#extension': point at the name instead.
  if (diag == Diag::ExtensionUnsupported && text.rfind(": ") != std::string::npos) {
    token = text.substr(text.rfind(": ") + 2);
    message = fmt::format(
        "extension '{}' is not supported: neither arbiter's table of legacy extensions nor "
        "glslang knows it",
        token);
  }

  compiler::Range range{0, 0};
  std::optional<SyntaxErrorPlace> syntax;
  if (diag == Diag::NestingTooDeep) {
    range = DeepestNesting(*file);
  } else if (line > 0 && token == "floating-point suffix") {
    range = FindFloatSuffix(*file, line);
  } else if (line > 0 && diag == Diag::SyntaxError && token.empty()) {
    // glslang quotes no token for a syntax error: find the one its message names.
    syntax = LocateSyntaxError(*file, static_cast<uint32_t>(line), message);
    range = syntax ? syntax->token : FindOnLine(*file, line, token);
  } else if (line > 0) {
    range = FindOnLine(*file, line, token);
  } else if (link) {
    // Place a link message at the construct it is about.
    std::string_view needle;
    if (diag == Diag::LinkFragColorAndData) needle = "gl_FragData";
    if (diag == Diag::LinkMissingFunction || diag == Diag::LinkRecursion) {
      // glslang names the function on the continuation: "f(" or "f(i1;".
      size_t colon = text.rfind(':');
      std::string_view tail =
          Trim(std::string_view(text).substr(colon == std::string::npos ? 0 : colon + 1));
      size_t paren = tail.find('(');
      if (paren != std::string_view::npos) needle = tail.substr(0, paren);
    }
    if (!needle.empty()) FindAnywhere(sources, needle, &file, &range);
  }
  compiler::Severity severity = (m.warning && diag != Diag::ReservedWord) || relaxed != nullptr
                                    ? compiler::Severity::Warning
                                    : compiler::Severity::Error;
  compiler::Diagnostic* reported = sink->Report(Info(diag), severity, file, range, message);
  if (reported != nullptr && syntax && syntax->missing_semicolon) {
    reported->notes.push_back(
        {file, *syntax->missing_semicolon, "the statement before it may be missing its ';'"});
  }
  return relaxed == nullptr;
}

}  // namespace

int ReportInfoLog(const char* log, const InfoLogContext& ctx, bool link,
                  compiler::DiagnosticSink* sink) {
  int relaxed = 0;
  if (log == nullptr || ctx.sources.empty()) return relaxed;
  std::vector<Message> messages;
  for (std::string_view rest(log); !rest.empty();) {
    size_t nl = rest.find('\n');
    std::string_view line = rest.substr(0, nl);
    rest = nl == std::string_view::npos ? std::string_view() : rest.substr(nl + 1);
    bool error = line.substr(0, 7) == "ERROR: ";
    bool warning = line.substr(0, 9) == "WARNING: ";
    if (error || warning) {
      messages.push_back(Message{warning, std::string(line.substr(error ? 7 : 9))});
    } else if (!messages.empty() && !Trim(line).empty()) {
      messages.back().body += " ";
      messages.back().body += Trim(line);
    }
  }
  for (const Message& m : messages) {
    // A return value glslang cannot convert at all is an error already; its warning about
    // converting return values (made an error in Emit) would say it twice.
    if (m.warning && m.body.find("type conversion on return values") != std::string::npos) {
      const std::string at = m.body.substr(0, m.body.find(": ") + 1);
      const bool known = std::any_of(messages.begin(), messages.end(), [&](const Message& e) {
        return !e.warning && e.body.compare(0, at.size(), at) == 0 &&
               e.body.find("cannot convert return value") != std::string::npos;
      });
      if (known) continue;
    }
    if (!Emit(m, ctx, link, sink)) ++relaxed;
  }
  return relaxed;
}

bool OnlyRelaxedErrors(const char* log, const InfoLogContext& ctx, bool link) {
  compiler::DiagnosticSink scratch(0);
  int relaxed = ReportInfoLog(log, ctx, link, &scratch);
  return relaxed > 0 && scratch.error_count() == 0;
}

}  // namespace arbiter::glsl
