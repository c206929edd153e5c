// SourceFile line table and location lookup, and whole-file reading and atomic writing.
#include "arbiter/compiler/source.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cassert>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <limits>
#include <system_error>
#include <thread>

#include "fmt/format.h"
#include "utf8.h"

namespace arbiter::compiler {

SourceFile::SourceFile(std::string path, std::string text)
    : path_(std::move(path)), text_(std::move(text)) {
  // Offsets are 32-bit; ReadFileBytes refuses larger inputs.
  assert(text_.size() <= std::numeric_limits<uint32_t>::max());
  line_starts_.push_back(0);
  const size_t size = text_.size();
  const char* const data = text_.data();
  // Most inputs end lines with "\n" alone: then memchr finds each line end, many bytes at a
  // time (every checked program builds this index, a few percent of checking).
  if (std::memchr(data, '\r', size) == nullptr) {
    line_starts_.reserve(size / 32 + 1);  // a guess: lines of program text are short
    const char* end = data + size;
    for (const char* p = data;
         (p = static_cast<const char*>(std::memchr(p, '\n', static_cast<size_t>(end - p))));) {
      ++p;
      if (p == end) break;  // a terminator at the very end opens no line
      line_starts_.push_back(static_cast<uint32_t>(p - data));
    }
    return;
  }
  for (size_t i = 0; i < size; ++i) {
    const char c = text_[i];
    if (c != '\n' && c != '\r') {
      continue;
    }
    if (c == '\r' && i + 1 < size && text_[i + 1] == '\n') {
      ++i;  // "\r\n" ends one line
    }
    // A terminator at the very end does not open another (empty) line.
    if (i + 1 < size) {
      line_starts_.push_back(static_cast<uint32_t>(i + 1));
    }
  }
}

LineCol SourceFile::Locate(uint32_t offset) const {
  const auto size = static_cast<uint32_t>(text_.size());
  offset = std::min(offset, size);
  // The last line start <= offset; line_starts_[0] == 0 so there is always one.
  const auto it = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
  const auto index = static_cast<uint32_t>(it - line_starts_.begin()) - 1;
  const uint32_t line = index + 1;
  const std::string_view text = LineText(line);
  // An offset inside the terminator (or at the end of the text) is the column just after
  // the last character of the line.
  const size_t stop = std::min<size_t>(offset - line_starts_[index], text.size());
  uint32_t column = 1;
  size_t pos = 0;
  while (pos < stop) {
    const size_t length = Utf8CharLength(text, pos);
    if (pos + length > stop) {
      break;  // the offset is inside this character: report the character's column
    }
    pos += length;
    ++column;
  }
  return LineCol{line, column};
}

std::string_view SourceFile::LineText(uint32_t line) const {
  assert(line >= 1 && line <= line_count());
  if (line < 1 || line > line_count()) {
    return {};
  }
  const size_t begin = line_starts_[line - 1];
  size_t end = line < line_count() ? line_starts_[line] : text_.size();
  // Drop the terminator: "\r\n", "\n" or "\r".
  if (end > begin && text_[end - 1] == '\n') {
    --end;
    if (end > begin && text_[end - 1] == '\r') {
      --end;
    }
  } else if (end > begin && text_[end - 1] == '\r') {
    --end;
  }
  return std::string_view(text_).substr(begin, end - begin);
}

uint32_t SourceFile::LineStart(uint32_t line) const {
  assert(line >= 1 && line <= line_count());
  if (line < 1 || line > line_count()) {
    return static_cast<uint32_t>(text_.size());
  }
  return line_starts_[line - 1];
}

namespace {

// The C library's description of an errno value, lower-cased ("no such file or directory").
std::string ErrnoReason(int error_number) {
  std::string reason = std::generic_category().message(error_number);
  // Lower-case the first letter of a word ("No such file" -> "no such file"), not of an
  // acronym ("I/O error" stays as it is).
  if (reason.size() >= 2 && reason[0] >= 'A' && reason[0] <= 'Z' && reason[1] >= 'a' &&
      reason[1] <= 'z') {
    reason[0] = static_cast<char>(reason[0] - 'A' + 'a');
  }
  return reason;
}

// Reads `stream` to its end into `bytes`.
bool ReadStream(std::FILE* stream, std::string* bytes, std::string* error) {
  char buffer[1 << 16];
  for (;;) {
    errno = 0;
    const size_t count = std::fread(buffer, 1, sizeof buffer, stream);
    bytes->append(buffer, count);
    if (count < sizeof buffer) {
      if (std::ferror(stream)) {
        *error = ErrnoReason(errno != 0 ? errno : EIO);
        return false;
      }
      return true;
    }
  }
}

// Checks the 32-bit offset limit of SourceFile.
bool CheckSize(const std::string& bytes, std::string* error) {
  if (bytes.size() > std::numeric_limits<uint32_t>::max()) {
    *error = "file too large (the limit is 4 GiB)";
    return false;
  }
  return true;
}

}  // namespace

bool ReadFileBytes(const std::string& path, std::string* bytes, std::string* error) {
  switch (ReadFileOrDirectory(path, bytes, error)) {
    case ReadOutcome::Read:
      return true;
    case ReadOutcome::Directory:
      *error = ErrnoReason(EISDIR);
      return false;
    case ReadOutcome::Failed:
      return false;
  }
  return false;
}

ReadOutcome ReadFileOrDirectory(const std::string& path, std::string* bytes, std::string* error) {
  bytes->clear();
  if (path == "-") {
    return ReadStream(stdin, bytes, error) && CheckSize(*bytes, error) ? ReadOutcome::Read
                                                                       : ReadOutcome::Failed;
  }
  // open, fstat, one read, close: a batch reads thousands of small files, and the system
  // calls were half of checking one (docs/performance.md).
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    *error = ErrnoReason(errno);
    return ReadOutcome::Failed;
  }
  struct stat info {};
  if (::fstat(fd, &info) != 0) {
    *error = ErrnoReason(errno);
    ::close(fd);
    return ReadOutcome::Failed;
  }
  if (S_ISDIR(info.st_mode)) {
    ::close(fd);
    return ReadOutcome::Directory;
  }
  // A regular file's size is known: ask for one byte more, and a short read is its end.
  // Pipes, devices and a file that grows go on until read says end of file.
  size_t chunk = S_ISREG(info.st_mode) ? static_cast<size_t>(info.st_size) + 1 : 1 << 16;
  bool ok = true;
  for (;;) {
    const size_t used = bytes->size();
    bytes->resize(used + chunk);
    const ssize_t count = ::read(fd, bytes->data() + used, chunk);
    if (count < 0 && errno == EINTR) {
      bytes->resize(used);
      continue;
    }
    if (count < 0) {
      *error = ErrnoReason(errno);
      ok = false;
      bytes->resize(used);
      break;
    }
    bytes->resize(used + static_cast<size_t>(count));
    if (count == 0 || (S_ISREG(info.st_mode) && static_cast<size_t>(count) < chunk)) break;
    chunk = 1 << 16;
  }
  ::close(fd);
  return ok && CheckSize(*bytes, error) ? ReadOutcome::Read : ReadOutcome::Failed;
}

namespace {

// Writes `bytes` to a new hidden temporary beside `path` (fsync'd, with the mode of the file it
// will replace) and sets `*temp` to its name; the first half of an atomic write.
bool WriteTemporary(const std::string& path, std::string_view bytes, std::string* temp_out,
                    std::string* error) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  if (target.filename().empty()) {
    *error = ErrnoReason(EISDIR);
    return false;
  }
  fs::path folder = target.parent_path();
  if (folder.empty()) {
    folder = ".";
  }

  // Keep the mode of a file we replace; a new file gets 0666 less the umask (open's rule).
  struct stat existing {};
  const bool replacing = ::stat(path.c_str(), &existing) == 0;
  if (replacing && S_ISDIR(existing.st_mode)) {
    *error = ErrnoReason(EISDIR);
    return false;
  }

  // A hidden temporary next to the target, so that rename() stays within one file system.
  std::string temp;
  int fd = -1;
  const auto unique =
      std::hash<std::thread::id>{}(std::this_thread::get_id()) ^
      static_cast<size_t>(std::chrono::steady_clock::now().time_since_epoch().count());
  for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
    temp = (folder / fmt::format(".{}.tmp-{}-{:x}-{}", target.filename().string(), ::getpid(),
                                 unique, attempt))
               .string();
    fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0 && errno != EEXIST) {
      *error = ErrnoReason(errno);
      return false;
    }
  }
  if (fd < 0) {
    *error = ErrnoReason(EEXIST);
    return false;
  }

  // On failure: remember errno, close and remove the temporary, report.
  const auto fail = [&](int error_number) {
    if (fd >= 0) {
      ::close(fd);
    }
    ::unlink(temp.c_str());
    *error = ErrnoReason(error_number);
    return false;
  };

  if (replacing && ::fchmod(fd, existing.st_mode & 07777) != 0) {
    return fail(errno);
  }
  const char* data = bytes.data();
  size_t remaining = bytes.size();
  while (remaining > 0) {
    const ssize_t written = ::write(fd, data, remaining);
    if (written < 0) {
      if (errno == EINTR) {
        continue;
      }
      return fail(errno);
    }
    data += written;
    remaining -= static_cast<size_t>(written);
  }
  if (::fsync(fd) != 0) {
    return fail(errno);
  }
  const int closed = ::close(fd);
  fd = -1;
  if (closed != 0) {
    return fail(errno);
  }
  *temp_out = temp;
  return true;
}

// The second half: the temporary replaces `path` (removed when that fails).
bool Publish(const std::string& temp, const std::string& path, std::string* error) {
  if (::rename(temp.c_str(), path.c_str()) != 0) {
    *error = ErrnoReason(errno);
    ::unlink(temp.c_str());
    return false;
  }
  // Make the rename itself durable; a failure here does not undo the write.
  std::filesystem::path folder = std::filesystem::path(path).parent_path();
  if (folder.empty()) folder = ".";
  const int folder_fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (folder_fd >= 0) {
    ::fsync(folder_fd);
    ::close(folder_fd);
  }
  return true;
}

}  // namespace

bool WriteFileAtomically(const std::string& path, std::string_view bytes, std::string* error) {
  std::string temp;
  return WriteTemporary(path, bytes, &temp, error) && Publish(temp, path, error);
}

bool WriteFilesAtomically(const std::vector<FileToWrite>& files, std::string* error) {
  std::vector<std::string> temps;
  for (const FileToWrite& f : files) {
    std::string temp;
    std::string reason;
    if (!WriteTemporary(f.path, f.bytes, &temp, &reason)) {
      for (const std::string& t : temps) ::unlink(t.c_str());
      *error = fmt::format("cannot write '{}': {}", f.path, reason);
      return false;
    }
    temps.push_back(std::move(temp));
  }
  // Every file is on disk: only renames are left, which fail only if a folder goes away.
  for (size_t i = 0; i < files.size(); ++i) {
    std::string reason;
    if (!Publish(temps[i], files[i].path, &reason)) {
      for (size_t j = i + 1; j < temps.size(); ++j) ::unlink(temps[j].c_str());
      *error = fmt::format("cannot write '{}': {}", files[i].path, reason);
      return false;
    }
  }
  return true;
}

}  // namespace arbiter::compiler
