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

#include <cctype>
#include <set>
#include <string>
#include <string_view>

#include "strict.h"

namespace arbiter::glsl {
namespace {

struct Word {
  std::string_view text;
  size_t offset;  // in the line
};

// The identifiers and numbers of a directive line (comments already blanked).
std::vector<Word> Words(std::string_view line) {
  std::vector<Word> out;
  for (size_t i = 0; i < line.size();) {
    if (IsIdentChar(line[i])) {
      size_t start = i;
      while (i < line.size() && IsIdentChar(line[i])) ++i;
      out.push_back({line.substr(start, i - start), start});
    } else {
      ++i;
    }
  }
  return out;
}

}  // namespace

void CheckPreprocessor(const StrictContext& ctx) {
  std::set<std::string, std::less<>> reserved_reported;  // once per name: at its first use
  for (size_t index = 0; index < ctx.sources.size(); ++index) {
    const compiler::SourceFile* file = ctx.sources[index];
    const std::string& text = BlankedText(ctx, index);
    std::set<std::string, std::less<>> macros = {"__LINE__", "__FILE__", "__VERSION__"};
    bool seen_code = false;  // a non-preprocessor token
    int depth = 0;           // brace depth: > 0 inside a function definition
    auto report = [&](Diag diag, size_t offset, size_t length, std::string message) {
      ctx.sink->Report(Info(diag), file,
                       {static_cast<uint32_t>(offset), static_cast<uint32_t>(offset + length)},
                       std::move(message));
    };
    size_t pos = 0;
    while (pos <= text.size()) {
      size_t end = text.find('\n', pos);
      if (end == std::string::npos) end = text.size();
      std::string_view line = std::string_view(text).substr(pos, end - pos);
      size_t first = line.find_first_not_of(" \t\r\f\v");
      if (first != std::string_view::npos && line[first] == '#') {
        std::vector<Word> words = Words(line.substr(first + 1));
        for (Word& w : words) w.offset += first + 1;
        std::string_view directive = words.empty() ? "" : words[0].text;
        const bool predefined =
            words.size() > 1 && (words[1].text == "__LINE__" || words[1].text == "__FILE__" ||
                                 words[1].text == "__VERSION__");
        if ((directive == "define" || directive == "undef") && predefined) {
          // 3.3: #define and #undef are "as is standard for C++ preprocessors", and C++
          // ([cpp.predefined]) forbids defining or undefining a predefined macro (Mesa agrees).
          report(Diag::Preprocessor, pos + words[1].offset, words[1].text.size(),
                 fmt::format("'{}' is a predefined macro: it cannot be {}", words[1].text,
                             directive == "define" ? "redefined" : "undefined"));
        } else if ((directive == "define" || directive == "undef") && words.size() > 1 &&
                   words[1].text.find("__") != std::string_view::npos) {
          report(Diag::ReservedIdentifier, pos + words[1].offset, words[1].text.size(),
                 fmt::format("macro names containing '__' are reserved ({} section 3.3); '{}' "
                             "is {} anyway, as every driver does",
                             VersionName(ctx), words[1].text,
                             directive == "define" ? "defined" : "undefined"));
        }
        if (directive == "define" && words.size() > 1) {
          macros.emplace(words[1].text);
        } else if (directive == "undef" && words.size() > 1) {
          macros.erase(std::string(words[1].text));
        } else if (directive == "extension" && seen_code) {
          report(Diag::Preprocessor, pos + words[0].offset, words[0].text.size(),
                 "#extension must come before any non-preprocessor token of the shader");
        } else if (directive == "pragma" && depth > 0 && words.size() > 1 &&
                   (words[1].text == "optimize" || words[1].text == "debug")) {
          report(Diag::Preprocessor, pos + words[0].offset, words[0].text.size(),
                 fmt::format("#pragma {} can only be used outside function definitions",
                             words[1].text));
        } else if (directive == "line") {
          for (size_t i = 1; i < words.size(); ++i) {
            if (IsIdentStart(words[i].text[0]) && !macros.count(words[i].text)) {
              report(Diag::Preprocessor, pos + words[i].offset, words[i].text.size(),
                     fmt::format("#line takes constant integer expressions; '{}' is not a "
                                 "defined macro",
                                 words[i].text));
              break;
            }
          }
        }
      } else if (first != std::string_view::npos) {
        seen_code = true;
        // 3.6: "all identifiers containing two consecutive underscores (__) are reserved as
        // possible future keywords" (the predefined macros excepted).
        for (const Word& w : Words(line)) {
          if (IsIdentStart(w.text[0]) && w.text.find("__") != std::string_view::npos &&
              !macros.count(w.text) && reserved_reported.emplace(w.text).second) {
            report(Diag::ReservedIdentifier, pos + w.offset, w.text.size(),
                   fmt::format("identifiers containing '__' are reserved as possible future "
                               "keywords ({} section 3.6): '{}'; every driver accepts it",
                               VersionName(ctx), w.text));
          }
        }
        for (char c : line) {
          if (c == '{') ++depth;
          if (c == '}' && depth > 0) --depth;
        }
      }
      pos = end + 1;
    }
  }
}

}  // namespace arbiter::glsl
