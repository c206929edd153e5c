// Limit keys and built-in profiles (from limits.def), and loading of JSON limit profiles.
#include "arbiter/compiler/limits.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "arbiter/compiler/source.h"
#include "fmt/format.h"
#include "nlohmann/json.hpp"

namespace arbiter::compiler {
namespace {

constexpr std::string_view kSpecMin = "spec-min";

// The built-in profiles, in the order of limits.def's value columns.
constexpr std::array<std::string_view, 7> kBuiltinNames = {kSpecMin, "mesa", "r300", "r500",
                                                           "i915",   "nv30", "nv40"};

LimitProfile MakeProfile(size_t column) {
  LimitProfile profile;
  profile.name = std::string(kBuiltinNames[column]);
  profile.base = profile.name;
#define ARBITER_LIMIT(key, gl, specmin, mesa, r300, r500, i915, nv30, nv40, desc) \
  profile.values.emplace(                                                         \
      key, std::array<int64_t, 7>{specmin, mesa, r300, r500, i915, nv30, nv40}[column]);
#include "limits.def"
#undef ARBITER_LIMIT
  return profile;
}

// Edit distance, for "did you mean" hints on misspelt keys.
size_t EditDistance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) {
    row[j] = j;
  }
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// " (did you mean 'x'?)" for the closest known key within a few edits, else "".
std::string SuggestKey(std::string_view unknown) {
  std::string_view best;
  size_t best_distance = 4;  // suggest only near misses
  for (const LimitKey& key : LimitKeys()) {
    const size_t distance = EditDistance(unknown, key.key);
    if (distance < best_distance) {
      best_distance = distance;
      best = key.key;
    }
  }
  return best.empty() ? std::string() : fmt::format(" (did you mean '{}'?)", best);
}

// "'spec-min', 'mesa', ... or 'nv40'".
std::string BuiltinNamesText() {
  std::string text;
  for (size_t i = 0; i < kBuiltinNames.size(); ++i) {
    if (i > 0) {
      text += i + 1 < kBuiltinNames.size() ? ", " : " or ";
    }
    text += fmt::format("'{}'", kBuiltinNames[i]);
  }
  return text;
}

// Strips nlohmann's "[json.exception.parse_error.101] " prefix from an exception text.
std::string JsonErrorText(const char* what) {
  std::string text(what);
  if (!text.empty() && text[0] == '[') {
    const size_t close = text.find("] ");
    if (close != std::string::npos) {
      text.erase(0, close + 2);
    }
  }
  return text;
}

// Applies the parsed document of limits file `path` over its base profile.
std::optional<LimitProfile> ProfileFromJson(const std::string& path, const nlohmann::json& document,
                                            std::string* error) {
  if (!document.is_object()) {
    *error = fmt::format("limits file '{}' must hold a JSON object", path);
    return std::nullopt;
  }
  for (const auto& member : document.items()) {
    if (member.key() != "name" && member.key() != "base" && member.key() != "limits" &&
        member.key() != "extensions") {
      *error = fmt::format(
          "unknown member '{}' in '{}' (expected 'name', 'base', 'limits' and 'extensions')",
          member.key(), path);
      return std::nullopt;
    }
  }

  std::string base_name(kSpecMin);
  if (const auto it = document.find("base"); it != document.end()) {
    if (!it->is_string()) {
      *error = fmt::format("'base' in '{}' must be a string ({})", path, BuiltinNamesText());
      return std::nullopt;
    }
    base_name = it->get<std::string>();
  }
  const LimitProfile* base = BuiltinProfile(base_name);
  if (base == nullptr) {
    *error = fmt::format("unknown base profile '{}' in '{}' (expected {})", base_name, path,
                         BuiltinNamesText());
    return std::nullopt;
  }
  LimitProfile profile = *base;
  profile.name = path;
  if (const auto it = document.find("name"); it != document.end()) {
    if (!it->is_string()) {
      *error = fmt::format("'name' in '{}' must be a string", path);
      return std::nullopt;
    }
    profile.name = it->get<std::string>();
  }

  if (const auto it = document.find("extensions"); it != document.end()) {
    bool strings = it->is_array() &&
                   std::all_of(it->begin(), it->end(), [](const auto& e) { return e.is_string(); });
    if (!strings) {
      *error = fmt::format("'extensions' in '{}' must be an array of extension names", path);
      return std::nullopt;
    }
    profile.glsl_extensions = it->get<std::vector<std::string>>();
  }

  if (const auto it = document.find("limits"); it != document.end()) {
    if (!it->is_object()) {
      *error = fmt::format("'limits' in '{}' must be an object of limit keys", path);
      return std::nullopt;
    }
    for (const auto& [key, value] : it->items()) {
      const auto slot = profile.values.find(key);
      if (slot == profile.values.end()) {
        *error = fmt::format("unknown limit key '{}' in '{}'{}", key, path, SuggestKey(key));
        return std::nullopt;
      }
      // Integers only: 3.0, true and "3" are refused, as are negative values.
      const bool integer = value.is_number_integer();
      const bool fits =
          value.is_number_unsigned()
              ? value.get<uint64_t>() <= static_cast<uint64_t>(std::numeric_limits<int64_t>::max())
              : integer && value.get<int64_t>() >= 0;
      if (!integer || !fits) {
        *error = fmt::format("limit '{}' in '{}' must be a non-negative integer, not {}", key, path,
                             value.dump());
        return std::nullopt;
      }
      slot->second = value.get<int64_t>();
    }
  }
  return profile;
}

}  // namespace

const std::vector<LimitKey>& LimitKeys() {
  static const std::vector<LimitKey> keys = {
#define ARBITER_LIMIT(key, gl, specmin, mesa, r300, r500, i915, nv30, nv40, desc) \
  LimitKey{key, gl, desc},
#include "limits.def"
#undef ARBITER_LIMIT
  };
  return keys;
}

int64_t LimitProfile::Get(std::string_view key) const {
  const auto it = values.find(key);
  assert(it != values.end() && "unknown limit key");
  return it != values.end() ? it->second : 0;
}

const LimitProfile* BuiltinProfile(std::string_view name) {
  static const std::vector<LimitProfile> profiles = [] {
    std::vector<LimitProfile> all;
    for (size_t column = 0; column < kBuiltinNames.size(); ++column) {
      all.push_back(MakeProfile(column));
    }
    return all;
  }();
  for (const LimitProfile& profile : profiles) {
    if (profile.name == name) {
      return &profile;
    }
  }
  return nullptr;
}

std::vector<std::string_view> BuiltinProfileNames() {
  return {kBuiltinNames.begin(), kBuiltinNames.end()};
}

std::optional<LimitProfile> LoadLimitProfile(const std::string& arg, std::string* error) {
  if (const LimitProfile* builtin = BuiltinProfile(arg)) {
    return *builtin;
  }
  std::string bytes;
  std::string reason;
  if (!ReadFileBytes(arg, &bytes, &reason)) {
    // A bare word that is no file was most likely meant as a profile name.
    if (arg.find_first_of("/.") == std::string::npos && arg != "-") {
      *error = fmt::format("unknown limit profile '{}' (expected {}, or a JSON file)", arg,
                           BuiltinNamesText());
    } else {
      *error = fmt::format("cannot read limits file '{}': {}", arg, reason);
    }
    return std::nullopt;
  }
  nlohmann::json document;
  try {
    document = nlohmann::json::parse(bytes);
  } catch (const nlohmann::json::exception& e) {
    *error = fmt::format("invalid JSON in '{}': {}", arg, JsonErrorText(e.what()));
    return std::nullopt;
  }
  return ProfileFromJson(arg, document, error);
}

}  // namespace arbiter::compiler
