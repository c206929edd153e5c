// "Did you mean" suggestions: the closest candidate by edit distance.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace arbiter::compiler {

// The candidate closest to `word` (case-insensitive match first, then Levenshtein distance
// of at most max(1, size/3)); empty when none is close.
std::string ClosestMatch(std::string_view word, const std::vector<std::string_view>& candidates);

// "a, b, c or d"
std::string JoinAlternatives(const std::vector<std::string_view>& words);

}  // namespace arbiter::compiler
