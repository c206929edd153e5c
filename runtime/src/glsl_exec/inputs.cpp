// The inputs of a GLSL run: the slots a --set may name, parsing --set and --uniform, and the
// JSON vectors file. See glsl_exec.h.
#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "arbiter/arbvp/exec_io.h"
#include "arbiter/runtime/glsl_exec.h"
#include "glsl_exec/types.h"

namespace arbiter::runtime {
namespace {

using glsl::Reflection;

bool ParseNumber(std::string_view text, float* value) {
  if (text == "inf" || text == "+inf") {
    *value = std::numeric_limits<float>::infinity();
    return true;
  }
  if (text == "-inf") {
    *value = -std::numeric_limits<float>::infinity();
    return true;
  }
  if (text == "nan") {
    *value = std::numeric_limits<float>::quiet_NaN();
    return true;
  }
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, *value);
  return ec == std::errc() && ptr == end && !text.empty();
}

// "1,2,3" -> numbers; false (with `error`) on a bad number.
bool ParseNumbers(std::string_view text, std::vector<float>* values, std::string* error) {
  values->clear();
  while (true) {
    const size_t comma = text.find(',');
    const std::string_view item = text.substr(0, comma);
    float value = 0.0f;
    if (!ParseNumber(item, &value)) {
      *error = fmt::format("'{}' is not a number (decimal, inf, -inf or nan)", item);
      return false;
    }
    values->push_back(value);
    if (comma == std::string_view::npos) return true;
    text.remove_prefix(comma + 1);
  }
}

bool SplitAssignment(std::string_view assignment, std::string* name, std::string_view* values,
                     std::string* error) {
  const size_t eq = assignment.find('=');
  if (eq == std::string_view::npos || eq == 0) {
    *error = fmt::format("'{}' is not NAME=V1,V2,..", assignment);
    return false;
  }
  *name = std::string(assignment.substr(0, eq));
  *values = assignment.substr(eq + 1);
  return true;
}

GlslInputSlot Builtin(std::string name, int components, int min_components, std::vector<float> fill,
                      const std::vector<glsl::BuiltinUse>& read) {
  GlslInputSlot slot;
  slot.type = components == 1 ? "float" : fmt::format("vec{}", components);
  slot.components = components;
  slot.min_components = min_components;
  slot.fill = std::move(fill);
  for (const glsl::BuiltinUse& use : read) {
    // "gl_TexCoord" read with a variable index reads every element of its size.
    bool element = false;
    if (name.starts_with(use.name + "[")) {
      const int index = std::atoi(name.c_str() + use.name.size() + 1);
      element = index < std::max(use.components / 4, 1);
    }
    slot.read |= use.name == name || element ||
                 (name.starts_with(use.name + ".") && use.name == "gl_FragCoord");
  }
  slot.name = std::move(name);
  return slot;
}

// User attributes or varyings: one slot per variable (arrays: one per element too).
void UserSlots(const std::vector<glsl::ReflectedVariable>& vars, bool need_read,
               std::vector<GlslInputSlot>* slots) {
  for (const glsl::ReflectedVariable& v : vars) {
    const glsl_exec::TypeInfo info = glsl_exec::LookUpType(v.type);
    if (info.components == 0 || info.base != glsl_exec::BaseKind::Float) continue;
    auto add = [&](std::string name) {
      GlslInputSlot slot;
      slot.name = std::move(name);
      slot.type = v.type;
      slot.components = info.components;
      slot.min_components = info.components;
      slot.read = need_read ? v.read : true;
      slot.fill.assign(static_cast<size_t>(info.components), 0.0f);
      slots->push_back(std::move(slot));
    };
    if (v.array_size == 0) {
      add(v.name);
    } else {
      for (int i = 0; i < v.array_size; ++i) add(fmt::format("{}[{}]", v.name, i));
    }
  }
}

}  // namespace

std::vector<GlslInputSlot> GlslInputSlots(const Reflection* vertex, const Reflection* fragment) {
  std::vector<GlslInputSlot> slots;
  const std::vector<float> zero1{0.0f};
  const std::vector<float> xyzw{0.0f, 0.0f, 0.0f, 1.0f};
  const std::vector<float> white{1.0f, 1.0f, 1.0f, 1.0f};
  if (vertex != nullptr) {
    const std::vector<glsl::BuiltinUse>& read = vertex->builtins_read;
    // GL's current values (GL 2.0 table 6.5) fill what is not set.
    slots.push_back(Builtin("gl_Vertex", 4, 2, xyzw, read));
    slots.push_back(Builtin("gl_Normal", 3, 3, {0.0f, 0.0f, 1.0f}, read));
    slots.push_back(Builtin("gl_Color", 4, 3, white, read));
    slots.push_back(Builtin("gl_SecondaryColor", 3, 3, {0.0f, 0.0f, 0.0f}, read));  // alpha: 1
    slots.push_back(Builtin("gl_FogCoord", 1, 1, zero1, read));
    for (int i = 0; i < arbvp::kMaxTextureCoords; ++i) {
      slots.push_back(Builtin(fmt::format("gl_MultiTexCoord{}", i), 4, 1, xyzw, read));
    }
    UserSlots(vertex->attributes, false, &slots);
    return slots;
  }
  if (fragment == nullptr) return slots;
  const std::vector<glsl::BuiltinUse>& read = fragment->builtins_read;
  slots.push_back(Builtin("gl_Color", 4, 1, white, read));
  slots.push_back(Builtin("gl_SecondaryColor", 4, 1, xyzw, read));
  for (int i = 0; i < arbvp::kMaxTextureCoords; ++i) {
    slots.push_back(Builtin(fmt::format("gl_TexCoord[{}]", i), 4, 1, xyzw, read));
  }
  slots.push_back(Builtin("gl_FogFragCoord", 1, 1, zero1, read));
  // x and y are the pixel's: only the window depth is an input.
  slots.push_back(Builtin("gl_FragCoord.z", 1, 1, {0.5f}, read));
  UserSlots(fragment->varyings, true, &slots);
  return slots;
}

bool ParseGlslSet(const std::vector<GlslInputSlot>& slots, std::string_view assignment,
                  std::string* name, std::vector<float>* values, std::string* error) {
  std::string_view text;
  if (!SplitAssignment(assignment, name, &text, error)) return false;
  auto slot = std::find_if(slots.begin(), slots.end(),
                           [&](const GlslInputSlot& s) { return s.name == *name; });
  if (slot == slots.end()) {
    std::vector<std::string> names;
    for (const GlslInputSlot& s : slots) {
      if (!s.name.starts_with("gl_") || s.read) names.push_back(s.name);
    }
    *error = fmt::format("--set {}: the run has no input '{}'; its inputs: {}", assignment, *name,
                         fmt::join(names, ", "));
    if (*name == "gl_FragCoord") {
      *error += " (gl_FragCoord.xy is the vector's pixel: set gl_FragCoord.z only)";
    }
    return false;
  }
  if (!ParseNumbers(text, values, error)) {
    *error = fmt::format("--set {}: {}", assignment, *error);
    return false;
  }
  const int count = static_cast<int>(values->size());
  if (count < slot->min_components || count > slot->components) {
    *error = fmt::format("--set {}: {} is a {} and takes {} value(s), not {}", assignment, *name,
                         slot->type,
                         slot->min_components == slot->components
                             ? fmt::format("{}", slot->components)
                             : fmt::format("{} to {}", slot->min_components, slot->components),
                         count);
    return false;
  }
  for (size_t c = values->size(); c < slot->fill.size(); ++c) values->push_back(slot->fill[c]);
  return true;
}

bool ParseGlslUniform(std::string_view assignment, std::string* name, std::vector<float>* values,
                      std::string* error) {
  std::string_view text;
  if (!SplitAssignment(assignment, name, &text, error) || !ParseNumbers(text, values, error)) {
    *error = fmt::format("--uniform {}: {}", assignment, *error);
    return false;
  }
  return true;
}

namespace {

bool JsonNumbers(const nlohmann::json& value, std::string* text, std::string* error) {
  std::vector<std::string> items;
  auto one = [&](const nlohmann::json& v) {
    if (v.is_number()) {
      items.push_back(fmt::format("{}", v.get<double>()));
    } else if (v.is_string()) {
      items.push_back(v.get<std::string>());
    } else {
      return false;
    }
    return true;
  };
  bool ok = true;
  if (value.is_array()) {
    for (const nlohmann::json& v : value) ok = ok && one(v);
  } else {
    ok = one(value);
  }
  if (!ok || items.empty()) {
    *error = "a value is a number, an array of numbers, or \"inf\", \"-inf\", \"nan\"";
    return false;
  }
  *text = fmt::format("{}", fmt::join(items, ","));
  return true;
}

}  // namespace

bool ParseGlslVectorsJson(std::string_view text, GlslExecInputs* inputs, std::string* error) {
  const nlohmann::json json = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (json.is_discarded() || !json.is_object()) {
    *error = "not a JSON object";
    return false;
  }
  // GL state and textures: the ARB exec's reader.
  nlohmann::json arb = nlohmann::json::object();
  std::vector<std::string> shared;
  for (const auto& [key, value] : json.items()) {
    if (key == "textures") {
      arb["textures"] = value;
    } else if (key == "set") {
      if (!value.is_object()) {
        *error = "\"set\" is an object of NAME: VALUE";
        return false;
      }
      for (const auto& [name, v] : value.items()) {
        if (name.starts_with("state.")) {
          arb["set"][name] = v;
          continue;
        }
        std::string numbers;
        if (!JsonNumbers(v, &numbers, error)) return false;
        shared.push_back(fmt::format("{}={}", name, numbers));
      }
    } else if (key == "uniforms") {
      if (!value.is_object()) {
        *error = "\"uniforms\" is an object of NAME: VALUE";
        return false;
      }
      for (const auto& [name, v] : value.items()) {
        std::string numbers;
        if (!JsonNumbers(v, &numbers, error)) return false;
        std::string parsed_name;
        std::vector<float> values;
        if (!ParseGlslUniform(fmt::format("{}={}", name, numbers), &parsed_name, &values, error))
          return false;
        inputs->uniforms.emplace_back(parsed_name, values);
      }
    } else if (key != "vectors") {
      *error = fmt::format("unknown member \"{}\" (set, uniforms, textures, vectors)", key);
      return false;
    }
  }
  arbvp::ExecInputs arb_inputs;
  arb_inputs.state = inputs->state;
  arb_inputs.textures = inputs->textures;
  if (!arbvp::ParseVectorsJson(arb.dump(), &arb_inputs, error)) return false;
  inputs->state = arb_inputs.state;
  inputs->textures = arb_inputs.textures;

  std::map<std::string, std::vector<float>> base;
  for (const GlslInputSlot& slot : inputs->slots) base[slot.name] = slot.fill;
  auto apply = [&](const std::string& assignment, std::map<std::string, std::vector<float>>* v) {
    std::string name;
    std::vector<float> values;
    if (!ParseGlslSet(inputs->slots, assignment, &name, &values, error)) return false;
    (*v)[name] = std::move(values);
    return true;
  };
  for (const std::string& assignment : shared) {
    if (!apply(assignment, &base)) return false;
  }
  inputs->vectors.clear();
  if (json.contains("vectors")) {
    const nlohmann::json& list = json["vectors"];
    if (!list.is_array()) {
      *error = "\"vectors\" is an array of objects";
      return false;
    }
    for (const nlohmann::json& entry : list) {
      if (!entry.is_object()) {
        *error = "\"vectors\" is an array of objects";
        return false;
      }
      std::map<std::string, std::vector<float>> v = base;
      for (const auto& [name, value] : entry.items()) {
        std::string numbers;
        if (!JsonNumbers(value, &numbers, error) ||
            !apply(fmt::format("{}={}", name, numbers), &v)) {
          return false;
        }
      }
      inputs->vectors.push_back(std::move(v));
    }
  }
  if (inputs->vectors.empty()) inputs->vectors.push_back(base);
  return true;
}

}  // namespace arbiter::runtime
