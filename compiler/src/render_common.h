// Helpers shared by the text, JSON and SARIF renderers (private).
#pragma once

#include <algorithm>
#include <cstdint>
#include <string_view>
#include <vector>

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

// The report's diagnostics in the order a reader expects: those without a file first (an
// unreadable input), then file by file in order of first appearance, by line within a file.
// Diagnostics on one line keep the order they were reported in, which is cause before
// consequence (glslang's "undeclared identifier" before the "cannot convert" it leads to).
inline std::vector<const Diagnostic*> InPositionOrder(const FileReport& report) {
  std::vector<const SourceFile*> files;
  auto file_rank = [&](const SourceFile* file) -> size_t {
    if (file == nullptr) return 0;
    auto it = std::find(files.begin(), files.end(), file);
    if (it == files.end()) it = files.insert(files.end(), file);
    return static_cast<size_t>(it - files.begin()) + 1;
  };
  struct Ranked {
    size_t file;
    uint32_t line;
    const Diagnostic* diagnostic;
  };
  std::vector<Ranked> ranked;
  ranked.reserve(report.diagnostics.size());
  for (const Diagnostic& d : report.diagnostics) {
    const uint32_t line = d.file != nullptr ? Resolve(*d.file, d.range).begin.line : 0;
    ranked.push_back({file_rank(d.file), line, &d});
  }
  std::stable_sort(ranked.begin(), ranked.end(), [](const Ranked& a, const Ranked& b) {
    return a.file != b.file ? a.file < b.file : a.line < b.line;
  });
  std::vector<const Diagnostic*> out;
  out.reserve(ranked.size());
  for (const Ranked& r : ranked) out.push_back(r.diagnostic);
  return out;
}

}  // namespace arbiter::compiler
