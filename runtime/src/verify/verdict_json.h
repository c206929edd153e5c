// Verdicts carried out of verify's worker processes. Floats travel as their bit patterns,
// so a value (NaN payloads and -0 included) arrives exactly as the worker saw it.
#pragma once

#include <nlohmann/json.hpp>

#include "arbiter/runtime/verify.h"

namespace arbiter::runtime {

nlohmann::json VerdictToJson(const Verdict& verdict);
// False when `json` is not what VerdictToJson writes.
[[nodiscard]] bool VerdictFromJson(const nlohmann::json& json, Verdict* verdict);

}  // namespace arbiter::runtime
