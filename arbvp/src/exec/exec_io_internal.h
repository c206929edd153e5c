// Pieces shared by the exec_io files (assignments, textures, JSON).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "arbiter/arbvp/exec.h"

namespace arbiter::arbvp {

using Values = std::vector<float>;

// A decimal float, inf, -inf or nan (a leading '+' allowed); the whole text must match.
bool ParseFloat(std::string_view text, float* out);
// Sets the named input (exec_io.h) to `values`.
bool Assign(std::string_view name, const Values& values, ExecInputs* inputs, InputVector* vector,
            std::string* error);
// A texture unit number in [0, kMaxTextureImageUnits).
bool ParseUnit(std::string_view s, int* unit);
// A texture object of the JSON vectors file.
bool ParseTextureJson(const nlohmann::json& j, Texture* t, std::string* error);
// A JSON number or one of the strings ParseFloat reads.
bool JsonFloat(const nlohmann::json& j, float* out);
// A number or a list of numbers; `what` names the value in errors.
bool JsonValues(const nlohmann::json& j, Values* out, std::string_view what, std::string* error);

}  // namespace arbiter::arbvp
