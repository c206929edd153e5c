// Tests of DiagnosticSink: ordering, counts, the error limit and warning promotion.
#include "arbiter/compiler/diagnostic.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace arbiter::compiler {
namespace {

constexpr DiagnosticInfo kError{"test-error", Severity::Error, "an error", ""};
constexpr DiagnosticInfo kWarning{"test-warning", Severity::Warning, "a warning", ""};
constexpr DiagnosticInfo kNote{"test-note", Severity::Note, "a remark", ""};

const SourceFile& File() {
  static const SourceFile file("a.vp", "!!ARBvp1.0\nEND\n");
  return file;
}

// The messages of the stored diagnostics, in order.
std::vector<std::string> Messages(const DiagnosticSink& sink) {
  std::vector<std::string> messages;
  for (const Diagnostic& diag : sink.diagnostics()) {
    messages.push_back(diag.message);
  }
  return messages;
}

TEST(DiagnosticSinkTest, StoresInOrderWithTheDefaultSeverity) {
  DiagnosticSink sink;
  sink.Report(kError, &File(), {0, 3}, "e1");
  sink.Report(kWarning, &File(), {4, 5}, "w1");
  sink.Report(kNote, &File(), {4, 5}, "n1");
  sink.Report(kError, nullptr, {}, "e2");
  EXPECT_EQ(Messages(sink), (std::vector<std::string>{"e1", "w1", "n1", "e2"}));
  EXPECT_EQ(sink.error_count(), 2);
  EXPECT_EQ(sink.warning_count(), 1);
  EXPECT_FALSE(sink.limit_reached());
  EXPECT_EQ(sink.dropped(), 0);
  const Diagnostic& first = sink.diagnostics()[0];
  EXPECT_EQ(first.info, &kError);
  EXPECT_EQ(first.severity, Severity::Error);
  EXPECT_EQ(first.file, &File());
  EXPECT_EQ(first.range.begin, 0u);
  EXPECT_EQ(first.range.end, 3u);
  EXPECT_EQ(sink.diagnostics()[1].severity, Severity::Warning);
  EXPECT_EQ(sink.diagnostics()[2].severity, Severity::Note);
}

TEST(DiagnosticSinkTest, ExplicitSeverityOverridesTheDefault) {
  DiagnosticSink sink;
  sink.Report(kWarning, Severity::Error, &File(), {0, 1}, "promoted");
  EXPECT_EQ(sink.error_count(), 1);
  EXPECT_EQ(sink.warning_count(), 0);
  EXPECT_EQ(sink.diagnostics()[0].severity, Severity::Error);
  EXPECT_EQ(sink.diagnostics()[0].info, &kWarning);
}

TEST(DiagnosticSinkTest, ReportReturnsTheStoredDiagnosticForNotes) {
  DiagnosticSink sink;
  Diagnostic* diag = sink.Report(kError, &File(), {0, 3}, "'x' redeclared");
  ASSERT_NE(diag, nullptr);
  diag->notes.push_back(Note{&File(), {4, 5}, "'x' first declared here"});
  ASSERT_EQ(sink.diagnostics()[0].notes.size(), 1u);
  EXPECT_EQ(sink.diagnostics()[0].notes[0].message, "'x' first declared here");
}

TEST(DiagnosticSinkTest, NoLimitByDefault) {
  DiagnosticSink sink;
  for (int i = 0; i < 1000; ++i) {
    sink.Report(kError, &File(), {0, 1}, "e");
  }
  EXPECT_EQ(sink.error_count(), 1000);
  EXPECT_EQ(sink.dropped(), 0);
}

TEST(DiagnosticSinkTest, ErrorLimitDropsLaterErrors) {
  DiagnosticSink sink(/*error_limit=*/2);
  EXPECT_NE(sink.Report(kError, &File(), {0, 1}, "e1"), nullptr);
  EXPECT_NE(sink.Report(kWarning, &File(), {0, 1}, "w1"), nullptr);
  EXPECT_NE(sink.Report(kError, &File(), {0, 1}, "e2"), nullptr);
  EXPECT_FALSE(sink.limit_reached());  // reached, but nothing dropped yet
  EXPECT_EQ(sink.Report(kError, &File(), {0, 1}, "e3"), nullptr);
  EXPECT_EQ(sink.Report(kError, &File(), {0, 1}, "e4"), nullptr);
  EXPECT_EQ(Messages(sink), (std::vector<std::string>{"e1", "w1", "e2"}));
  EXPECT_EQ(sink.error_count(), 2);
  EXPECT_EQ(sink.warning_count(), 1);
  EXPECT_TRUE(sink.limit_reached());
  EXPECT_EQ(sink.dropped(), 2);
}

TEST(DiagnosticSinkTest, WarningsAndNotesPastTheLimitAreDroppedUncounted) {
  DiagnosticSink sink(/*error_limit=*/1);
  sink.Report(kError, &File(), {0, 1}, "e1");
  EXPECT_EQ(sink.Report(kWarning, &File(), {0, 1}, "w1"), nullptr);
  EXPECT_EQ(sink.Report(kNote, &File(), {0, 1}, "n1"), nullptr);
  EXPECT_EQ(Messages(sink), std::vector<std::string>{"e1"});
  EXPECT_EQ(sink.warning_count(), 0);
  EXPECT_EQ(sink.dropped(), 0);
  EXPECT_FALSE(sink.limit_reached());
}

TEST(DiagnosticSinkTest, PromoteWarnings) {
  DiagnosticSink sink;
  sink.Report(kWarning, &File(), {0, 1}, "w1");
  sink.Report(kError, &File(), {0, 1}, "e1");
  sink.Report(kNote, &File(), {0, 1}, "n1");
  sink.Report(kWarning, &File(), {0, 1}, "w2");
  sink.PromoteWarnings();
  EXPECT_EQ(Messages(sink), (std::vector<std::string>{"w1", "e1", "n1", "w2"}));
  EXPECT_EQ(sink.error_count(), 3);
  EXPECT_EQ(sink.warning_count(), 0);
  EXPECT_EQ(sink.diagnostics()[0].severity, Severity::Error);
  EXPECT_EQ(sink.diagnostics()[2].severity, Severity::Note);
  EXPECT_EQ(sink.diagnostics()[3].severity, Severity::Error);
  EXPECT_EQ(sink.dropped(), 0);
}

TEST(DiagnosticSinkTest, PromoteWarningsAppliesTheLimitInReportOrder) {
  DiagnosticSink sink(/*error_limit=*/2);
  sink.Report(kWarning, &File(), {0, 1}, "w1");
  sink.Report(kError, &File(), {0, 1}, "e1");
  sink.Report(kNote, &File(), {0, 1}, "n1");
  sink.Report(kWarning, &File(), {0, 1}, "w2");
  sink.Report(kError, &File(), {0, 1}, "e2");
  sink.PromoteWarnings();
  // As if reported as errors: w1 and e1 fit, everything after them is dropped.
  EXPECT_EQ(Messages(sink), (std::vector<std::string>{"w1", "e1"}));
  EXPECT_EQ(sink.error_count(), 2);
  EXPECT_EQ(sink.dropped(), 2);
  EXPECT_TRUE(sink.limit_reached());
}

TEST(DiagnosticSinkTest, PromoteWarningsCountsWarningsDroppedPastTheLimit) {
  DiagnosticSink sink(/*error_limit=*/1);
  sink.Report(kError, &File(), {0, 1}, "e1");
  sink.Report(kWarning, &File(), {0, 1}, "w1");  // dropped: the limit is reached
  sink.Report(kError, &File(), {0, 1}, "e2");    // dropped
  EXPECT_EQ(sink.dropped(), 1);
  sink.PromoteWarnings();
  EXPECT_EQ(Messages(sink), std::vector<std::string>{"e1"});
  EXPECT_EQ(sink.dropped(), 2);
}

// -Wno-<code> removes that code's warnings, -Werror=<code> makes them errors; other codes
// and errors are untouched, and -Werror still promotes the rest.
TEST(DiagnosticSinkTest, WarningPolicyPerCode) {
  const DiagnosticInfo other{"test-other", Severity::Warning, "another warning", ""};
  DiagnosticSink sink;
  sink.Report(kWarning, &File(), {0, 1}, "w1");
  sink.Report(other, &File(), {0, 1}, "o1");
  sink.Report(kError, &File(), {0, 1}, "e1");
  WarningPolicy policy;
  policy.codes[std::string(kWarning.code)] = WarningAction::Off;
  policy.codes["test-other"] = WarningAction::Error;
  sink.ApplyWarningPolicy(policy);
  EXPECT_EQ(Messages(sink), (std::vector<std::string>{"o1", "e1"}));
  EXPECT_EQ(sink.error_count(), 2);
  EXPECT_EQ(sink.warning_count(), 0);

  DiagnosticSink kept;
  kept.Report(kWarning, &File(), {0, 1}, "w1");
  kept.Report(other, &File(), {0, 1}, "o1");
  WarningPolicy werror;
  werror.werror = true;
  werror.codes["test-other"] = WarningAction::Off;
  kept.ApplyWarningPolicy(werror);
  EXPECT_EQ(Messages(kept), std::vector<std::string>{"w1"});
  EXPECT_EQ(kept.error_count(), 1);
}

TEST(DiagnosticSinkTest, PromoteWarningsTwiceChangesNothing) {
  DiagnosticSink sink(/*error_limit=*/3);
  sink.Report(kWarning, &File(), {0, 1}, "w1");
  sink.Report(kError, &File(), {0, 1}, "e1");
  sink.PromoteWarnings();
  sink.PromoteWarnings();
  EXPECT_EQ(Messages(sink), (std::vector<std::string>{"w1", "e1"}));
  EXPECT_EQ(sink.error_count(), 2);
  EXPECT_EQ(sink.dropped(), 0);
}

TEST(DiagnosticSinkTest, SeverityNames) {
  EXPECT_EQ(SeverityName(Severity::Error), "error");
  EXPECT_EQ(SeverityName(Severity::Warning), "warning");
  EXPECT_EQ(SeverityName(Severity::Note), "note");
}

}  // namespace
}  // namespace arbiter::compiler
