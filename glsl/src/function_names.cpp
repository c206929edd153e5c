// GLSL 1.10's separate name space of functions, for glslang (function_names.h). A function is
// found at file level as `type name (`, a const variable as `name =` in a const declaration;
// a name that is also a structure's (a constructor's, 4.1.8) is left as it is.
#include "function_names.h"

#include <set>
#include <string_view>
#include <vector>

#include "scan.h"

namespace arbiter::glsl {
namespace {

struct Names {
  std::set<std::string_view> functions;
  std::set<std::string_view> consts;
  std::set<std::string_view> structs;
};

// Function declarations, const declarators and structure names of one text's tokens.
void Collect(const std::vector<Token>& tokens, Names* names) {
  int braces = 0;
  for (size_t i = 0; i < tokens.size(); ++i) {
    std::string_view t = tokens[i].text;
    if (t == "{") ++braces;
    if (t == "}") --braces;
    const bool word = tokens[i].kind == Token::Identifier;
    if (word && braces == 0 && i > 0 && i + 1 < tokens.size() &&
        tokens[i - 1].kind == Token::Identifier && tokens[i + 1].text == "(") {
      names->functions.insert(t);
    }
    if (word && t == "struct" && i + 1 < tokens.size()) names->structs.insert(tokens[i + 1].text);
    if (t != "const") continue;
    // Declarators up to the ';'; a parameter ("const in float x") ends at ')' or ','.
    int depth = 0;
    for (size_t j = i + 1; j + 1 < tokens.size(); ++j) {
      std::string_view u = tokens[j].text;
      if (u == "(" || u == "[" || u == "{") ++depth;
      if (u == ")" || u == "]" || u == "}") {
        if (depth-- == 0) break;
      }
      if (depth == 0 && u == ";") break;
      if (depth == 0 && u == "=" && tokens[j - 1].kind == Token::Identifier &&
          tokens[j + 1].text != "=") {
        names->consts.insert(tokens[j - 1].text);
      }
    }
  }
}

// A name as long as `name` that no word of `words` is: `name` with its first characters
// made '_', or for a one-letter name another letter (glslang's text only, never shown); empty
// if every one is taken.
std::string Alias(std::string_view name, const std::set<std::string>& words) {
  std::vector<std::string> candidates;
  for (size_t n = 1; n <= name.size(); ++n) {
    candidates.push_back(std::string(n, '_') + std::string(name.substr(n)));
  }
  for (char c = 'a'; name.size() == 1 && c <= 'z'; ++c) candidates.emplace_back(1, c);
  for (const std::string& alias : candidates) {
    if (words.count(alias) == 0) return alias;
  }
  return {};
}

// Renames `from` to `to` (same length) where it is followed by '(' and not preceded by '.',
// comments aside; directives included, so that a macro calling the function calls it still.
void RenameCalls(std::string* text, std::string_view from, std::string_view to) {
  const std::string blanked = BlankComments(*text);
  auto blank = [](char c) { return IsLineBlank(c) || c == '\n'; };
  ForEachWord(blanked, [&](size_t begin, size_t end) {
    if (std::string_view(blanked).substr(begin, end - begin) != from) return;
    size_t after = end;
    while (after < blanked.size() && blank(blanked[after])) ++after;
    size_t before = begin;
    while (before > 0 && blank(blanked[before - 1])) --before;
    const bool call = after < blanked.size() && blanked[after] == '(';
    if (call && (before == 0 || blanked[before - 1] != '.')) text->replace(begin, to.size(), to);
  });
}

}  // namespace

std::vector<Rename> SeparateFunctionNames(const std::vector<std::string*>& texts) {
  Names names;
  std::vector<std::vector<Token>> tokens;
  tokens.reserve(texts.size());
  for (const std::string* text : texts) {
    tokens.push_back(Tokenize(*text));
    Collect(tokens.back(), &names);
  }
  std::vector<Rename> renames;
  std::set<std::string> words;  // every word of the texts (macros too), and the names given
  for (const std::string* text : texts) {
    ForEachWord(*text,
                [&](size_t begin, size_t end) { words.insert(text->substr(begin, end - begin)); });
  }
  for (std::string_view function : names.functions) {
    if (names.consts.count(function) == 0 || names.structs.count(function) != 0) continue;
    std::string alias = Alias(function, words);
    if (alias.empty()) continue;
    words.insert(alias);
    renames.push_back({alias, std::string(function)});
  }
  for (const Rename& r : renames) {
    for (std::string* text : texts) RenameCalls(text, r.user, r.glslang);
  }
  return renames;
}

}  // namespace arbiter::glsl
