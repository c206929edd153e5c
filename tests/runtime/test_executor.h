// The Mesa executor the GL tests share: one per process (a context per test would cost most
// of the run on llvmpipe), with the backend and driver of ARBITER_TEST_BACKEND and
// ARBITER_TEST_DRIVER (ctest runs each combination as its own process).
#pragma once

#include <string>

#include "arbiter/runtime/exec.h"

namespace arbiter::runtime::testing {

// ARBITER_TEST_DRIVER, "softpipe" when unset.
std::string TestDriver();

// The process's executor, created on first use; null (with `error`) when it cannot be.
ArbExecutor* SharedExecutor(std::string* error);

}  // namespace arbiter::runtime::testing
