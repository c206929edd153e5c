// Source text: the bytes of one input and line/column lookup from byte offsets.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace arbiter::compiler {

// A half-open byte range [begin, end) in one SourceFile.
struct Range {
  uint32_t begin = 0;
  uint32_t end = 0;
};

// A 1-based line and 1-based column. Columns count characters (UTF-8 decoded), so a
// multi-byte character in a comment advances the column by one.
struct LineCol {
  uint32_t line = 1;
  uint32_t column = 1;
};

// Owns the bytes of one input. "\n", "\r\n" and "\r" each end one line (both ARB specs
// treat carriage return as whitespace and as a comment terminator).
class SourceFile {
 public:
  SourceFile(std::string path, std::string text);

  const std::string& path() const { return path_; }
  const std::string& text() const { return text_; }

  // Line and column of a byte offset (offset == size() is the end of the text).
  LineCol Locate(uint32_t offset) const;
  // Number of lines (a final line without terminator counts; an empty file has one line).
  uint32_t line_count() const { return static_cast<uint32_t>(line_starts_.size()); }
  // The text of a 1-based line, without its terminator.
  std::string_view LineText(uint32_t line) const;
  // Byte offset at which a 1-based line starts.
  uint32_t LineStart(uint32_t line) const;

 private:
  std::string path_;
  std::string text_;
  std::vector<uint32_t> line_starts_;
};

// Reads a whole file ("-" reads standard input). On failure returns false and sets `error`
// to a lower-case reason ("no such file or directory", "is a directory", "permission
// denied", ...) without the path. Inputs over 4 GiB are refused (offsets are 32-bit).
[[nodiscard]] bool ReadFileBytes(const std::string& path, std::string* bytes, std::string* error);

// ReadFileBytes that tells a directory apart instead of failing on it: one open serves to
// learn what a path names and to read it (a batch names thousands of files).
enum class ReadOutcome { Read, Directory, Failed };
[[nodiscard]] ReadOutcome ReadFileOrDirectory(const std::string& path, std::string* bytes,
                                              std::string* error);

// Writes `bytes` to `path` atomically (temporary file in the same folder, fsync, then
// rename; the temporary is removed on failure). A replaced file keeps its permissions.
// "-" is not special here: writing to standard output is the caller's business. On
// failure returns false and sets `error` to a lower-case reason, as ReadFileBytes.
[[nodiscard]] bool WriteFileAtomically(const std::string& path, std::string_view bytes,
                                       std::string* error);

// Several files that belong together (a translation's shaders and binding map): each is
// written to a temporary first, and only when all are on disk are they renamed into place, so
// a failure leaves none of them written (the renames themselves fail only if a folder goes
// away meanwhile). On failure returns false and sets `error` to "cannot write 'PATH': reason".
struct FileToWrite {
  std::string path;
  std::string bytes;
};
[[nodiscard]] bool WriteFilesAtomically(const std::vector<FileToWrite>& files, std::string* error);

}  // namespace arbiter::compiler
