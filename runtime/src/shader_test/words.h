// The small text helpers of the shader_test reader: piglit's commands are sscanf patterns
// in which parentheses, commas (and a stray semicolon) only separate numbers.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace arbiter::runtime::shader_test {

std::string_view Trim(std::string_view text);

// The words of a command line: a `#` starts a comment; `(`, `)`, `,` and `;` separate
// like blanks.
std::vector<std::string> Words(std::string_view line);

// A float as piglit reads one: decimal, inf/INF, nan/NAN, or 0x... as the bits of an IEEE
// single. False when `word` is not entirely a number.
bool ParseFloat(const std::string& word, float* value);
bool ParseDouble(const std::string& word, double* value);
bool ParseInt(const std::string& word, int* value);
bool ParseUint(const std::string& word, unsigned* value);

// Parses words[first, first + count) as floats; false when there are not `count` or one
// is not a number.
bool ParseFloats(const std::vector<std::string>& words, size_t first, size_t count, float* values);

}  // namespace arbiter::runtime::shader_test
