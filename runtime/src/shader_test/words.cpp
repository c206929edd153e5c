// Text helpers of the shader_test reader: see words.h.
#include "shader_test/words.h"

#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>

namespace arbiter::runtime::shader_test {

std::string_view Trim(std::string_view text) {
  const char* blanks = " \t\r\n\f\v";
  size_t begin = text.find_first_not_of(blanks);
  if (begin == std::string_view::npos) return {};
  size_t end = text.find_last_not_of(blanks);
  return text.substr(begin, end - begin + 1);
}

std::vector<std::string> Words(std::string_view line) {
  std::vector<std::string> words;
  std::string word;
  for (char c : line) {
    if (c == '#') break;
    if (c == ' ' || c == '\t' || c == '\r' || c == '(' || c == ')' || c == ',' || c == ';') {
      if (!word.empty()) words.push_back(std::move(word));
      word.clear();
    } else {
      word.push_back(c);
    }
  }
  if (!word.empty()) words.push_back(std::move(word));
  return words;
}

bool ParseFloat(const std::string& word, float* value) {
  if (word.size() > 2 && word[0] == '0' && (word[1] == 'x' || word[1] == 'X')) {
    unsigned bits = 0;
    if (!ParseUint(word, &bits)) return false;
    std::memcpy(value, &bits, sizeof bits);
    return true;
  }
  double d = 0.0;
  if (!ParseDouble(word, &d)) return false;
  *value = static_cast<float>(d);
  return true;
}

bool ParseDouble(const std::string& word, double* value) {
  if (word.empty()) return false;
  char* end = nullptr;
  *value = std::strtod(word.c_str(), &end);
  return end != word.c_str() && *end == '\0';
}

bool ParseInt(const std::string& word, int* value) {
  if (word.empty()) return false;
  char* end = nullptr;
  errno = 0;
  long v = std::strtol(word.c_str(), &end, 0);
  if (end == word.c_str() || *end != '\0' || errno != 0 || v < INT32_MIN || v > INT32_MAX) {
    return false;
  }
  *value = static_cast<int>(v);
  return true;
}

bool ParseUint(const std::string& word, unsigned* value) {
  if (word.empty() || word[0] == '-') return false;
  char* end = nullptr;
  errno = 0;
  unsigned long v = std::strtoul(word.c_str(), &end, 0);
  if (end == word.c_str() || *end != '\0' || errno != 0 || v > UINT32_MAX) return false;
  *value = static_cast<unsigned>(v);
  return true;
}

bool ParseFloats(const std::vector<std::string>& words, size_t first, size_t count, float* values) {
  if (words.size() < first + count) return false;
  for (size_t i = 0; i < count; ++i) {
    if (!ParseFloat(words[first + i], &values[i])) return false;
  }
  return true;
}

}  // namespace arbiter::runtime::shader_test
