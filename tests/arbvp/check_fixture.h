// Test fixture for the ARB checker: check a program text, inspect its diagnostics.
#pragma once

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "arbiter/arbvp/check.h"
#include "arbiter/compiler/limits.h"

namespace arbiter::arbvp {

// One reported diagnostic in a comparable form.
struct Reported {
  std::string code;
  uint32_t line = 0;
  uint32_t column = 0;
  compiler::Severity severity = compiler::Severity::Error;
  std::string message;
};

struct Checked {
  std::unique_ptr<compiler::SourceFile> source;
  CheckResult result;
  std::vector<Reported> diags;

  // The errors only / the warnings only.
  std::vector<Reported> Errors() const;
  std::vector<Reported> Warnings() const;
  // "line:col code" of every error, for EXPECT_THAT(..., ElementsAre(...)).
  std::vector<std::string> ErrorKeys() const;
  std::vector<std::string> WarningKeys() const;
  // All diagnostics as text, for failure messages.
  std::string Dump() const;
};

// Checks `text` (a whole program with header) with the given options.
Checked Check(const std::string& text, const CheckOptions& options);
// Checks `text` (a whole program with header). `profile` null: Mesa's limits (the default).
Checked Check(const std::string& text, const compiler::LimitProfile* profile = nullptr);
// Wraps body lines in "!!ARBvp1.0\n" ... "END\n" (so body line 1 is program line 2).
Checked CheckVp(const std::string& body, const compiler::LimitProfile* profile = nullptr);
Checked CheckFp(const std::string& body, const compiler::LimitProfile* profile = nullptr);

}  // namespace arbiter::arbvp
