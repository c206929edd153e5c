// Messages: their text form and the parse of glslang's info log.
#include "messages.h"

#include <glslang/Public/ShaderLang.h>

#include <charconv>
#include <mutex>
#include <utility>

namespace arbiter::targets {
namespace {

// Removes `prefix` from the front of `*text`; says whether it was there.
bool Consume(std::string_view* text, std::string_view prefix) {
  if (!text->starts_with(prefix)) return false;
  text->remove_prefix(prefix.size());
  return true;
}

// "<digits>:" at the front of `*text`, consumed; -1 when absent (and nothing consumed).
int ConsumeNumber(std::string_view* text) {
  int value = 0;
  auto [end, error] = std::from_chars(text->data(), text->data() + text->size(), value);
  if (error != std::errc() || end == text->data() + text->size() || *end != ':') return -1;
  text->remove_prefix(static_cast<size_t>(end - text->data()) + 1);
  return value;
}

}  // namespace

std::string FormatMessage(const Message& message) {
  std::string out = message.tool + ": ";
  if (message.line > 0) out += "line " + std::to_string(message.line) + ": ";
  out += message.severity == Message::Severity::Error ? "error: " : "warning: ";
  return out + message.text;
}

void AddMessage(std::vector<Message>* messages, Message::Severity severity, std::string tool,
                int line, std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  messages->push_back(Message{severity, std::move(tool), line, std::move(text)});
}

void AddGlslangLog(std::string_view log, std::vector<Message>* messages) {
  bool continues = false;  // an indented line continues the last message
  while (!log.empty()) {
    size_t eol = log.find('\n');
    std::string_view line = log.substr(0, eol);
    log.remove_prefix(eol == std::string_view::npos ? log.size() : eol + 1);
    while (!line.empty() && (line.back() == ' ' || line.back() == '\r')) line.remove_suffix(1);
    Message::Severity severity;
    if (Consume(&line, "ERROR: ") || Consume(&line, "INTERNAL ERROR: ")) {
      severity = Message::Severity::Error;
    } else if (Consume(&line, "WARNING: ")) {
      severity = Message::Severity::Warning;
    } else {
      if (continues && !line.empty()) {
        messages->back().text += '\n';
        messages->back().text += line;
      }
      continue;
    }
    continues = false;
    // The summary, and the note that glslang stopped at the first errors: nothing to add.
    if (line.ends_with("No code generated.") || line.ends_with("'' : compilation terminated")) {
      continue;
    }
    // "<string>:<line>: " (string 0: the one text we pass).
    std::string_view rest = line;
    int line_number = 0;
    if (ConsumeNumber(&rest) >= 0) {
      int number = ConsumeNumber(&rest);
      if (number >= 0) {
        line_number = number;
        line = rest;
        Consume(&line, " ");
      }
    }
    AddMessage(messages, severity, "glslang", line_number, std::string(line));
    continues = true;
  }
}

void EnsureGlslang() {
  static std::once_flag once;
  std::call_once(once, [] { glslang::InitializeProcess(); });
}

}  // namespace arbiter::targets
