// GLSL 1.10 section 3.3 (the preprocessor), where glslang 12 is laxer than the 1.10 text:
// - "#extension ... directives must occur before any non-preprocessor tokens";
// - "#pragma optimize/debug ... can only be used outside function definitions";
// - identifiers and macro names containing "__" are reserved (glslang only warns);
// - "#line must have, after macro substitution, [the form] #line line [source-string-number]
//   where line and source-string-number are constant integer expressions" (glslang takes an
//   undefined identifier as 0, silently).
// Read from the directive lines of the source, as a preprocessor does: these rules are about
// the text before macro expansion, which the AST no longer has.
#include <fmt/format.h>

#include <algorithm>
#include <iterator>
#include <set>
#include <string>
#include <string_view>
#include <vector>

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

// The rules of one source, in text order: its directives and the tokens of its code.
class Preprocessor {
 public:
  Preprocessor(const StrictContext& ctx, const compiler::SourceFile* file,
               std::set<std::string, std::less<>>* reserved_reported)
      : ctx_(ctx), file_(file), reserved_reported_(reserved_reported) {}

  void Follow(const Directive& d) {
    const std::vector<Token> words = Operands(d);
    const bool names_macro = (d.name == "define" || d.name == "undef") && !words.empty();
    if (names_macro) CheckMacroName(d.name, words[0]);
    if (d.name == "define") CheckStringification(d);
    if (d.name == "define" && !words.empty()) {
      macros_.emplace(words[0].text);
    } else if (d.name == "undef" && !words.empty()) {
      macros_.erase(std::string(words[0].text));
    } else if (d.name == "extension" && !d.before_code) {
      Report(Diag::Preprocessor, d.name_offset, d.name.size(),
             "#extension must come before any non-preprocessor token of the shader");
    } else if (d.name == "pragma" && d.brace_depth > 0 && !words.empty() &&
               (words[0].text == "optimize" || words[0].text == "debug")) {
      Report(
          Diag::Preprocessor, d.name_offset, d.name.size(),
          fmt::format("#pragma {} can only be used outside function definitions", words[0].text));
    } else if (d.name == "line") {
      CheckLine(words);
    }
  }

  // 3.6: "all identifiers containing two consecutive underscores (__) are reserved as
  // possible future keywords" (the predefined macros excepted).
  void CheckCode(const Token& t) {
    if (t.kind == Token::Identifier && t.text.find("__") != std::string_view::npos &&
        !macros_.count(t.text) && reserved_reported_->emplace(t.text).second) {
      Report(Diag::ReservedIdentifier, t.offset, t.text.size(),
             fmt::format("identifiers containing '__' are reserved as possible future "
                         "keywords ({} section 3.6): '{}'; every driver accepts it",
                         VersionName(ctx_), t.text));
    }
  }

 private:
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
      if (w.kind == Token::Identifier && !macros_.count(w.text)) {
        Report(Diag::Preprocessor, w.offset, w.text.size(),
               fmt::format("#line takes constant integer expressions; '{}' is not a "
                           "defined macro",
                           w.text));
        return;
      }
    }
  }

  const StrictContext& ctx_;
  const compiler::SourceFile* file_;
  std::set<std::string, std::less<>>* reserved_reported_;  // once per name: at its first use
  std::set<std::string, std::less<>> macros_ = {"__LINE__", "__FILE__", "__VERSION__"};
};

}  // namespace

void CheckPreprocessor(const StrictContext& ctx) {
  std::set<std::string, std::less<>> reserved_reported;
  for (size_t index = 0; index < ctx.sources.size(); ++index) {
    const std::string& text = BlankedText(ctx, index);
    Preprocessor preprocessor(ctx, ctx.sources[index], &reserved_reported);
    // The macros defined so far decide what a code token is: walk both in text order.
    const std::vector<Token> code = Tokenize(text);
    auto next = code.begin();
    for (const Directive& d : Directives(text)) {
      for (; next != code.end() && next->offset < d.hash; ++next) preprocessor.CheckCode(*next);
      preprocessor.Follow(d);
    }
    for (; next != code.end(); ++next) preprocessor.CheckCode(*next);
  }
}

}  // namespace arbiter::glsl
