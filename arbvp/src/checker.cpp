// CheckProgram: header, lexer, parser, then the check families in a fixed order.
#include <fmt/format.h>

#include "arbiter/arbvp/check.h"
#include "check/checks.h"
#include "diag.h"
#include "parser.h"

namespace arbiter::arbvp {
namespace {

constexpr std::string_view kVpHeader = "!!ARBvp1.0";
constexpr std::string_view kFpHeader = "!!ARBfp1.0";

// Finds the header; reports what is wrong with it. Returns false when unusable.
bool ParseHeader(const compiler::SourceFile& source, compiler::DiagnosticSink* sink,
                 ProgramKind* kind) {
  std::string_view text = source.text();
  if (text.substr(0, kVpHeader.size()) == kVpHeader) {
    *kind = ProgramKind::Vertex;
    return true;
  }
  if (text.substr(0, kFpHeader.size()) == kFpHeader) {
    *kind = ProgramKind::Fragment;
    return true;
  }
  const compiler::DiagnosticInfo& info = Info(Diag::HeaderMissing);
  size_t first = text.find_first_not_of(" \t\r\n\f\v");
  if (text.empty() || first == std::string_view::npos) {
    sink->Report(Info(Diag::InputEmpty), &source, {0, 0},
                 text.empty() ? "the program is empty; expected '!!ARBvp1.0' or '!!ARBfp1.0'"
                              : "the program holds only whitespace; expected '!!ARBvp1.0' or "
                                "'!!ARBfp1.0'");
    return false;
  }
  std::string_view rest = text.substr(first);
  auto line_end = rest.find_first_of("\r\n");
  std::string_view shown = rest.substr(0, std::min<size_t>(line_end, 24));
  std::string message;
  if (text.substr(0, 3) == "\xEF\xBB\xBF") {
    message =
        "the program starts with a UTF-8 byte-order mark; '!!ARBvp1.0' or '!!ARBfp1.0' "
        "must be the very first bytes";
  } else if (rest.substr(0, kVpHeader.size()) == kVpHeader ||
             rest.substr(0, kFpHeader.size()) == kFpHeader) {
    message =
        "the header must be the very first bytes of the program; remove the whitespace "
        "before it";
  } else if (rest.substr(0, 5) == "!!ARB") {
    message = fmt::format(
        "unsupported program header '{}'; expected '!!ARBvp1.0' or "
        "'!!ARBfp1.0'",
        shown);
  } else if (rest.substr(0, 2) == "!!") {
    message = fmt::format(
        "'{}' is not an ARB program header (NV and ATI program formats are "
        "not supported); expected '!!ARBvp1.0' or '!!ARBfp1.0'",
        shown);
  } else {
    message = "missing program header: an ARB program begins with '!!ARBvp1.0' or '!!ARBfp1.0'";
  }
  sink->Report(info, &source, {0, 0}, message);
  return false;
}

}  // namespace

bool LooksLikeArbProgram(std::string_view text) { return text.substr(0, 5) == "!!ARB"; }

CheckResult CheckProgram(const compiler::SourceFile& source, const CheckOptions& options,
                         compiler::DiagnosticSink* sink) {
  CheckResult result;
  ProgramKind kind;
  int errors_before = sink->error_count() + sink->dropped();
  int counted_before = sink->error_count();
  if (!ParseHeader(source, sink, &kind)) return result;
  Range header{0, static_cast<uint32_t>(kVpHeader.size())};
  if (options.expected_kind && *options.expected_kind != kind) {
    bool want_vp = *options.expected_kind == ProgramKind::Vertex;
    sink->Report(Info(Diag::HeaderStage), &source, header,
                 fmt::format("expected a {} program ('{}'), but the header says '{}'",
                             want_vp ? "vertex" : "fragment", want_vp ? kVpHeader : kFpHeader,
                             want_vp ? kFpHeader : kVpHeader));
    return result;
  }
  result.program = ParseProgram(source, kind, header, sink);
  CheckContext ctx{*result.program, source, sink, options.profile, &result.stats, counted_before};
  CheckProgramOptions(ctx);
  CheckBindings(ctx);
  CheckOperands(ctx);
  if (kind == ProgramKind::Fragment) CheckTextures(ctx);
  CheckResources(ctx);
  result.ok = sink->error_count() + sink->dropped() == errors_before;
  return result;
}

}  // namespace arbiter::arbvp
