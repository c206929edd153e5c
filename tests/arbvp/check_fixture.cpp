// Test fixture for the ARB checker.
#include "check_fixture.h"

namespace arbiter::arbvp {

std::vector<Reported> Checked::Errors() const {
  std::vector<Reported> out;
  for (const Reported& r : diags) {
    if (r.severity == compiler::Severity::Error) out.push_back(r);
  }
  return out;
}

std::vector<Reported> Checked::Warnings() const {
  std::vector<Reported> out;
  for (const Reported& r : diags) {
    if (r.severity == compiler::Severity::Warning) out.push_back(r);
  }
  return out;
}

static std::vector<std::string> Keys(const std::vector<Reported>& list) {
  std::vector<std::string> out;
  for (const Reported& r : list) {
    out.push_back(std::to_string(r.line) + ":" + std::to_string(r.column) + " " + r.code);
  }
  return out;
}

std::vector<std::string> Checked::ErrorKeys() const { return Keys(Errors()); }
std::vector<std::string> Checked::WarningKeys() const { return Keys(Warnings()); }

std::string Checked::Dump() const {
  std::string out;
  for (const Reported& r : diags) {
    out += std::to_string(r.line) + ":" + std::to_string(r.column) + " " + r.code + ": " +
           r.message + "\n";
  }
  return out;
}

Checked Check(const std::string& text, const CheckOptions& options) {
  Checked c;
  c.source = std::make_unique<compiler::SourceFile>("test", text);
  compiler::DiagnosticSink sink(0);
  c.result = CheckProgram(*c.source, options, &sink);
  for (const compiler::Diagnostic& d : sink.diagnostics()) {
    compiler::LineCol lc = c.source->Locate(d.range.begin);
    c.diags.push_back({std::string(d.info->code), lc.line, lc.column, d.severity, d.message});
  }
  return c;
}

Checked Check(const std::string& text, const compiler::LimitProfile* profile) {
  CheckOptions options;
  options.profile = profile;
  return Check(text, options);
}

Checked CheckVp(const std::string& body, const compiler::LimitProfile* profile) {
  return Check("!!ARBvp1.0\n" + body + "END\n", profile);
}

Checked CheckFp(const std::string& body, const compiler::LimitProfile* profile) {
  return Check("!!ARBfp1.0\n" + body + "END\n", profile);
}

}  // namespace arbiter::arbvp
