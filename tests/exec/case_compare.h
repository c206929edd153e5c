// Comparing an engine's results with a case's expectations (cases.h): shared by the
// reference interpreter's test and the Mesa engines' test.
#pragma once

#include <string>

#include "arbiter/arbvp/exec.h"
#include "cases.h"

namespace arbiter::exec_cases {

// The comparison of cases.h: Exact is bit equality (any NaN matches any NaN).
bool Matches(float got, float want, Tolerance tolerance, float bound);

// The outputs of one vector as text, for failure messages.
std::string Describe(const arbvp::VectorResult& r);

}  // namespace arbiter::exec_cases
