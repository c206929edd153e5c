// Helpers shared by the text, JSON and SARIF renderers (private).
#pragma once

#include <algorithm>
#include <cstdint>
#include <string_view>

#include "arbiter/compiler/render.h"

namespace arbiter::compiler {

// The path shown for a diagnostic or note: its file's path, else its own `path` field,
// else the report's path.
inline std::string_view PathOf(const FileReport& report, const SourceFile* file,
                               std::string_view own_path) {
  if (file != nullptr) {
    return file->path();
  }
  if (!own_path.empty()) {
    return own_path;
  }
  return report.path;
}

// A range resolved to 1-based line/column positions (end exclusive) and bytes, with both
// ends clamped to the text and end >= begin.
struct ResolvedRange {
  LineCol begin;
  LineCol end;
  uint32_t offset = 0;
  uint32_t length = 0;
};

inline ResolvedRange Resolve(const SourceFile& file, Range range) {
  const auto size = static_cast<uint32_t>(file.text().size());
  const uint32_t begin = std::min(range.begin, size);
  const uint32_t end = std::clamp(range.end, begin, size);
  return ResolvedRange{file.Locate(begin), file.Locate(end), begin, end - begin};
}

}  // namespace arbiter::compiler
