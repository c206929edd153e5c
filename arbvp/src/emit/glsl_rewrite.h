// Rewriting GLSL text at the level of identifiers and calls: what the dialect passes
// (emit_target.cpp) and the sampler emulation (sampler_emulation.cpp) edit the GLSL 1.10 the
// rest of the emitter writes with.
#pragma once

#include <cctype>
#include <string>
#include <vector>

namespace arbiter::arbvp::emit {

inline bool IsIdentChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// `text` with each identifier replaced by what `replace(word, text, &at)` returns (`at` is
// the index after the word; the callback may advance it past what it consumed); `//`
// comments are copied as they are.
template <typename F>
std::string ReplaceIdentifiers(const std::string& text, F replace) {
  std::string out;
  out.reserve(text.size() + 64);
  size_t i = 0;
  while (i < text.size()) {
    if (text.compare(i, 2, "//") == 0) {
      size_t end = text.find('\n', i);
      if (end == std::string::npos) end = text.size();
      out.append(text, i, end - i);
      i = end;
      continue;
    }
    if (!IsIdentChar(text[i]) || (i > 0 && IsIdentChar(text[i - 1]))) {
      out.push_back(text[i++]);
      continue;
    }
    size_t end = i;
    while (end < text.size() && IsIdentChar(text[end])) ++end;
    const std::string word = text.substr(i, end - i);
    i = end;
    out += replace(word, text, &i);
  }
  return out;
}

// The arguments of the call whose '(' is at `open` in `text`, split at the commas outside
// parentheses and trimmed; `*close` is the index of its ')'. False without a matching ')'.
inline bool CallArguments(const std::string& text, size_t open, std::vector<std::string>* args,
                          size_t* close) {
  args->clear();
  if (open >= text.size() || text[open] != '(') return false;
  int depth = 0;
  size_t begin = open + 1;
  for (size_t i = open; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '(') {
      ++depth;
    } else if (c == ')' && --depth == 0) {
      args->push_back(text.substr(begin, i - begin));
      *close = i;
      break;
    } else if (c == ',' && depth == 1) {
      args->push_back(text.substr(begin, i - begin));
      begin = i + 1;
    }
  }
  if (depth != 0) return false;
  for (std::string& a : *args) {
    const size_t first = a.find_first_not_of(' ');
    const size_t last = a.find_last_not_of(' ');
    a = first == std::string::npos ? "" : a.substr(first, last - first + 1);
  }
  return true;
}

}  // namespace arbiter::arbvp::emit
