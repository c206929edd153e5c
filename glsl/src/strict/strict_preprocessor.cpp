// GLSL 1.10 section 3.3 (the preprocessor), where glslang 12 is laxer than the 1.10 text:
// - "#extension ... directives must occur before any non-preprocessor tokens";
// - "#pragma optimize/debug ... can only be used outside function definitions";
// - identifiers and macro names containing "__" are reserved (glslang only warns);
// - "#line must have, after macro substitution, [the form] #line line [source-string-number]
//   where line and source-string-number are constant integer expressions" (glslang takes an
//   undefined identifier as 0, silently);
// - "There are no number sign based operators (no #, #@, ##, etc.)".
// Read from the directive lines of the source, as a preprocessor does: these rules are about
// the text before macro expansion, which the AST no longer has.
//
// Only the text a preprocessor processes is judged (conditionals.h). 3.3's conditionals
// "operate as is standard for C++ preprocessors", and C++ (16.1 [cpp.cond]) processes a
// skipped group's directives only through their name, to count nesting: a #define there
// defines nothing, so its name and '#' are not checked, nor its #line, #extension or
// #pragma; its code is no identifiers. In a group whose condition arbiter cannot evaluate,
// nothing is reported either, rather than a false error. None of these rules is about the
// characters themselves (3.1's character set is charset.cpp's, on all the text).
#include <fmt/format.h>

#include <algorithm>
#include <iterator>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "../conditionals.h"
#include "strict.h"

namespace arbiter::glsl {
namespace {

bool Predefined(std::string_view name) {
  return name == "__LINE__" || name == "__FILE__" || name == "__VERSION__";
}

// The identifiers and numbers after a directive's name: its operands, punctuation aside.
std::vector<Token> Operands(const Directive& d) {
  std::vector<Token> out;
  std::ranges::copy_if(d.words, std::back_inserter(out),
                       [](const Token& t) { return t.kind != Token::Punct; });
  return out;
}

// The rules of the whole shader, in text order: its directives and the tokens of its code.
class Preprocessor {
 public:
  explicit Preprocessor(const StrictContext& ctx) : ctx_(ctx), tracker_(ctx.preamble) {}

  // One source string, after those before it.
  void Read(size_t index) {
    file_ = ctx_.sources[index];
    code_seen_ = false;
    brace_depth_ = 0;
    const std::vector<Token>& code = SourceTokens(ctx_, index);
    auto next = code.begin();
    for (const Directive& d : Directives(BlankedText(ctx_, index))) {
      for (; next != code.end() && next->offset < d.hash; ++next) Code(*next);
      Follow(d);
    }
    for (; next != code.end(); ++next) Code(*next);
  }

 private:
  void Follow(const Directive& d) {
    if (tracker_.Follow(d).reach != Reach::Active) return;
    const std::vector<Token> words = Operands(d);
    const bool names_macro = (d.name == "define" || d.name == "undef") && !words.empty();
    if (names_macro) CheckMacroName(d.name, words[0]);
    if (d.name == "define") {
      CheckStringification(d);
    } else if (d.name == "extension" && code_seen_) {
      Report(Diag::Preprocessor, d.name_offset, d.name.size(),
             "#extension must come before any non-preprocessor token of the shader");
    } else if (d.name == "pragma" && brace_depth_ > 0 && !words.empty() &&
               (words[0].text == "optimize" || words[0].text == "debug")) {
      Report(
          Diag::Preprocessor, d.name_offset, d.name.size(),
          fmt::format("#pragma {} can only be used outside function definitions", words[0].text));
    } else if (d.name == "line") {
      CheckLine(words);
    }
  }

  // A token of code. Braces count where the text may be compiled (a function's body);
  // tokens before an #extension only where it surely is.
  void Code(const Token& t) {
    const Reach reach = tracker_.reach();
    if (reach != Reach::Skipped && t.text == "{") ++brace_depth_;
    if (reach != Reach::Skipped && t.text == "}" && brace_depth_ > 0) --brace_depth_;
    if (reach != Reach::Active) return;
    code_seen_ = true;
    CheckReservedIdentifier(t);
  }

  // 3.6: "all identifiers containing two consecutive underscores (__) are reserved as
  // possible future keywords" (the predefined macros excepted).
  void CheckReservedIdentifier(const Token& t) {
    if (t.kind == Token::Identifier && t.text.find("__") != std::string_view::npos &&
        !IsMacro(t.text) && reserved_reported_.emplace(t.text).second) {
      Report(Diag::ReservedIdentifier, t.offset, t.text.size(),
             fmt::format("identifiers containing '__' are reserved as possible future "
                         "keywords ({} section 3.6): '{}'; every driver accepts it",
                         VersionName(ctx_), t.text));
    }
  }

  // A macro here, or perhaps one (a name the implementation or an included file may define).
  bool IsMacro(std::string_view name) const {
    return Predefined(name) || tracker_.macros().count(name) > 0 || tracker_.MaybeMacro(name);
  }

  void Report(Diag diag, size_t offset, size_t length, std::string message) {
    ctx_.sink->Report(Info(diag), file_,
                      {static_cast<uint32_t>(offset), static_cast<uint32_t>(offset + length)},
                      std::move(message));
  }

  // GLSL 1.10 and 1.20 3.3: "There are no number sign based operators (no #, #@, ##, etc.)";
  // glslang stringifies a macro parameter. ## is glslang's to report (it does, by version).
  void CheckStringification(const Directive& d) {
    for (size_t i = 0; i < d.words.size(); ++i) {
      const Token& t = d.words[i];
      auto touches = [&](size_t j) {
        return j < d.words.size() && d.words[j].text == "#" &&
               (d.words[j].offset + 1 == t.offset || t.offset + 1 == d.words[j].offset);
      };
      if (t.text != "#" || touches(i + 1) || (i > 0 && touches(i - 1))) continue;
      Report(Diag::Preprocessor, t.offset, 1,
             fmt::format("'#' in a macro: the {} preprocessor has no number-sign operators, no "
                         "stringification (section 3.3)",
                         VersionName(ctx_)));
    }
  }

  // The name of a #define or #undef.
  void CheckMacroName(std::string_view directive, const Token& name) {
    if (Predefined(name.text)) {
      // 3.3: #define and #undef are "as is standard for C++ preprocessors", and C++
      // ([cpp.predefined]) forbids defining or undefining a predefined macro (Mesa agrees).
      Report(Diag::Preprocessor, name.offset, name.text.size(),
             fmt::format("'{}' is a predefined macro: it cannot be {}", name.text,
                         directive == "define" ? "redefined" : "undefined"));
    } else if (name.text.find("__") != std::string_view::npos) {
      Report(Diag::ReservedIdentifier, name.offset, name.text.size(),
             fmt::format("macro names containing '__' are reserved ({} section 3.3); '{}' "
                         "is {} anyway, as every driver does",
                         VersionName(ctx_), name.text,
                         directive == "define" ? "defined" : "undefined"));
    }
  }

  // #line's operands are constant integer expressions: an identifier must be a macro.
  void CheckLine(const std::vector<Token>& words) {
    for (const Token& w : words) {
      if (w.kind == Token::Identifier && !IsMacro(w.text)) {
        Report(Diag::Preprocessor, w.offset, w.text.size(),
               fmt::format("#line takes constant integer expressions; '{}' is not a "
                           "defined macro",
                           w.text));
        return;
      }
    }
  }

  const StrictContext& ctx_;
  GroupTracker tracker_;
  const compiler::SourceFile* file_ = nullptr;            // the source being read
  bool code_seen_ = false;                                // in this source, where it is Active
  int brace_depth_ = 0;                                   // in this source, where it is not Skipped
  std::set<std::string, std::less<>> reserved_reported_;  // once per name: at its first use
};

}  // namespace

void CheckPreprocessor(const StrictContext& ctx) {
  Preprocessor preprocessor(ctx);
  for (size_t index = 0; index < ctx.sources.size(); ++index) preprocessor.Read(index);
}

}  // namespace arbiter::glsl
