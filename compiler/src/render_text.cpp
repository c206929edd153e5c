// Text renderer: `path:line:col: error: message [code]`, the source line and a caret line.
#include <algorithm>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "arbiter/compiler/render.h"
#include "fmt/format.h"
#include "render_common.h"
#include "utf8.h"

namespace arbiter::compiler {
namespace {

constexpr size_t kTabStop = 8;
// Source lines wider than this (in columns, after tab expansion) are clipped to a window
// of kClipWidth columns around the caret, with "..." where text was cut.
constexpr size_t kMaxLineWidth = 200;
constexpr size_t kClipWidth = 160;
constexpr std::string_view kEllipsis = "...";

// ANSI escape sequences (used only when TextOptions::color is set).
constexpr std::string_view kReset = "\x1b[0m";
constexpr std::string_view kBold = "\x1b[1m";
constexpr std::string_view kRed = "\x1b[1;31m";
constexpr std::string_view kMagenta = "\x1b[1;35m";
constexpr std::string_view kCyan = "\x1b[1;36m";
constexpr std::string_view kGreen = "\x1b[1;32m";

std::string_view SeverityColor(Severity severity) {
  switch (severity) {
    case Severity::Note:
      return kCyan;
    case Severity::Warning:
      return kMagenta;
    case Severity::Error:
      return kRed;
  }
  return kRed;
}

// Appends `text` wrapped in `color` (or plain when colour is off).
void AppendStyled(std::string* out, std::string_view text, std::string_view color, bool use_color) {
  if (use_color) {
    *out += color;
    *out += text;
    *out += kReset;
  } else {
    *out += text;
  }
}

// The first line of a diagnostic or note: "path:line:col: note: message [code]", or
// "path: ..." without a location, or "note: ..." when `path` is empty too.
void AppendHeader(std::string* out, std::string_view path, const SourceFile* file, uint32_t offset,
                  Severity severity, std::string_view message, std::string_view code,
                  bool use_color) {
  std::string location;
  if (file != nullptr) {
    const LineCol lc = file->Locate(offset);
    location = fmt::format("{}:{}:{}:", path, lc.line, lc.column);
  } else if (!path.empty()) {
    location = fmt::format("{}:", path);
  }
  if (!location.empty()) {
    AppendStyled(out, location, kBold, use_color);
    *out += ' ';
  }
  AppendStyled(out, fmt::format("{}:", SeverityName(severity)), SeverityColor(severity), use_color);
  *out += ' ';
  *out += message;
  if (!code.empty()) {
    *out += fmt::format(" [{}]", code);
  }
  *out += '\n';
}

// One source line laid out in display cells: a tab becomes spaces to the next tab stop,
// every other character one cell. Control characters (C0, DEL, C1) print as a space and
// invalid UTF-8 bytes as '?', so the output stays printable and every cell is one column.
struct LaidOutLine {
  std::vector<std::string_view> cells;
  std::vector<size_t> first_cell;  // per byte of the line (+1): cell where its char starts
  std::vector<size_t> end_cell;    // per byte: cell just after its character
};

LaidOutLine LayOut(std::string_view line) {
  LaidOutLine laid;
  laid.first_cell.resize(line.size() + 1);
  laid.end_cell.resize(line.size() + 1);
  size_t pos = 0;
  while (pos < line.size()) {
    const size_t length = Utf8CharLength(line, pos);
    const size_t first = laid.cells.size();
    const auto byte = static_cast<uint8_t>(line[pos]);
    if (byte == '\t') {
      const size_t spaces = kTabStop - first % kTabStop;
      laid.cells.insert(laid.cells.end(), spaces, " ");
    } else if (byte < 0x20 || byte == 0x7F ||
               (length == 2 && byte == 0xC2 && static_cast<uint8_t>(line[pos + 1]) < 0xA0)) {
      laid.cells.emplace_back(" ");  // C0, DEL and C1 controls: never sent to a terminal
    } else if (!Utf8IsValidAt(line, pos)) {
      laid.cells.emplace_back("?");
    } else {
      laid.cells.push_back(line.substr(pos, length));
    }
    for (size_t i = pos; i < pos + length; ++i) {
      laid.first_cell[i] = first;
      laid.end_cell[i] = laid.cells.size();
    }
    pos += length;
  }
  laid.first_cell[line.size()] = laid.cells.size();
  laid.end_cell[line.size()] = laid.cells.size();
  return laid;
}

// The source line of `range.begin` and a caret line: '^' under the first character of the
// range and '~' under the rest of it on that line.
void AppendSnippet(std::string* out, const SourceFile& file, Range range, bool use_color) {
  const auto size = static_cast<uint32_t>(file.text().size());
  const uint32_t begin = std::min(range.begin, size);
  const uint32_t end = std::clamp(range.end, begin, size);
  const LineCol lc = file.Locate(begin);
  const std::string_view line = file.LineText(lc.line);
  const uint32_t line_start = file.LineStart(lc.line);
  const LaidOutLine laid = LayOut(line);

  // Caret cells [caret_begin, caret_end): an offset past the line's text (its terminator,
  // the end of the file) is the cell just after the last character.
  const size_t begin_byte = std::min<size_t>(begin - line_start, line.size());
  const size_t caret_begin = laid.first_cell[begin_byte];
  size_t caret_end = laid.cells.size();
  if (end - line_start <= line.size()) {
    caret_end = end > begin ? laid.end_cell[end - line_start - 1] : caret_begin;
  }
  caret_end = std::max(caret_end, caret_begin + 1);

  // Trailing blanks are not shown.
  size_t width = laid.cells.size();
  while (width > 0 && laid.cells[width - 1] == " ") {
    --width;
  }

  // Clip a long line to a window that holds the caret.
  size_t window_begin = 0;
  size_t window_end = width;
  if (width > kMaxLineWidth) {
    window_begin = caret_begin > kClipWidth / 2 ? caret_begin - kClipWidth / 2 : 0;
    if (window_begin + kClipWidth > width) {
      window_begin = width - kClipWidth;
    }
    window_end = window_begin + kClipWidth;
  }
  const bool clipped_left = window_begin > 0;
  const bool clipped_right = window_end < width;

  if (clipped_left) {
    *out += kEllipsis;
  }
  for (size_t i = window_begin; i < window_end; ++i) {
    *out += laid.cells[i];
  }
  if (clipped_right) {
    *out += kEllipsis;
  }
  *out += '\n';

  const size_t indent = (clipped_left ? kEllipsis.size() : 0) + (caret_begin - window_begin);
  if (clipped_right) {
    caret_end = std::min(caret_end, std::max(window_end, caret_begin + 1));
  }
  std::string marks = "^";
  marks.append(caret_end - caret_begin - 1, '~');
  out->append(indent, ' ');
  AppendStyled(out, marks, kGreen, use_color);
  *out += '\n';
}

}  // namespace

std::string RenderText(const FileReport& report, const TextOptions& options) {
  std::string out;
  for (const Diagnostic* d : InPositionOrder(report)) {
    const Diagnostic& diag = *d;
    const std::string_view code = diag.info != nullptr ? diag.info->code : std::string_view();
    AppendHeader(&out, PathOf(report, diag.file, diag.path), diag.file, diag.range.begin,
                 diag.severity, diag.message, code, options.color);
    if (diag.file != nullptr && options.show_source) {
      AppendSnippet(&out, *diag.file, diag.range, options.color);
    }
    for (const Note& note : diag.notes) {
      const std::string_view path =
          note.file != nullptr ? std::string_view(note.file->path()) : std::string_view();
      AppendHeader(&out, path, note.file, note.range.begin, Severity::Note, note.message, {},
                   options.color);
      if (note.file != nullptr && options.show_source) {
        AppendSnippet(&out, *note.file, note.range, options.color);
      }
    }
  }
  if (report.dropped_errors > 0) {
    const std::string message =
        fmt::format("{} more error{} not shown (--error-limit)", report.dropped_errors,
                    report.dropped_errors == 1 ? "" : "s");
    AppendHeader(&out, report.path, nullptr, 0, Severity::Note, message, {}, options.color);
  }
  return out;
}

}  // namespace arbiter::compiler
