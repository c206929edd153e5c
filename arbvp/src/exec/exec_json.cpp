// The JSON vectors file, results as JSON, and comparing results.
#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <utility>

#include "arbiter/arbvp/exec_io.h"
#include "exec/exec_io_internal.h"

namespace arbiter::arbvp {
namespace {

bool ApplyObject(const nlohmann::json& obj, std::string_view where, ExecInputs* inputs,
                 InputVector* vector, std::string* error) {
  if (!obj.is_object()) {
    *error = fmt::format("'{}' is an object of name: value pairs", where);
    return false;
  }
  Values values;
  for (const auto& [name, value] : obj.items()) {
    if (!JsonValues(value, &values, name, error) || !Assign(name, values, inputs, vector, error)) {
      *error = fmt::format("{}: {}", where, *error);
      return false;
    }
  }
  return true;
}

}  // namespace

bool JsonFloat(const nlohmann::json& j, float* out) {
  if (j.is_number()) {
    *out = j.get<float>();
    return true;
  }
  if (j.is_string()) return ParseFloat(j.get<std::string>(), out);
  return false;
}

bool JsonValues(const nlohmann::json& j, Values* out, std::string_view what, std::string* error) {
  out->clear();
  float v = 0.0f;
  if (JsonFloat(j, &v)) {
    out->push_back(v);
    return true;
  }
  if (j.is_array()) {
    for (const auto& e : j) {
      if (!JsonFloat(e, &v)) {
        *error = fmt::format("'{}': {} is not a number", what, e.dump());
        return false;
      }
      out->push_back(v);
    }
    return true;
  }
  *error = fmt::format("'{}': {} is not a number or a list of numbers", what, j.dump());
  return false;
}

bool ParseVectorsJson(std::string_view text, ExecInputs* inputs, std::string* error) {
  nlohmann::json j = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded() || !j.is_object()) {
    *error = "not a JSON object";
    return false;
  }
  for (const auto& [key, value] : j.items()) {
    if (key != "set" && key != "textures" && key != "vectors") {
      *error = fmt::format("unknown key '{}' (set, textures, vectors)", key);
      return false;
    }
  }
  // "set" may hold per-vector names too: they then apply to every vector, as flags do.
  InputVector base;
  if (auto it = j.find("set"); it != j.end()) {
    if (!ApplyObject(*it, "set", inputs, &base, error)) return false;
  }
  if (auto it = j.find("textures"); it != j.end()) {
    if (!it->is_object()) {
      *error = "'textures' maps texture units to textures";
      return false;
    }
    for (const auto& [unit_text, tex] : it->items()) {
      int unit = 0;
      Texture t;
      if (!ParseUnit(unit_text, &unit)) {
        *error = fmt::format("textures: '{}' is no texture unit in [0, {})", unit_text,
                             kMaxTextureImageUnits);
        return false;
      }
      if (!ParseTextureJson(tex, &t, error)) {
        *error = fmt::format("textures: unit {}: {}", unit, *error);
        return false;
      }
      inputs->textures[unit] = std::move(t);
    }
  }
  if (auto it = j.find("vectors"); it != j.end()) {
    if (!it->is_array()) {
      *error = "'vectors' is a list of objects";
      return false;
    }
    for (size_t i = 0; i < it->size(); ++i) {
      InputVector v = base;
      if (!ApplyObject((*it)[i], fmt::format("vectors[{}]", i), inputs, &v, error)) return false;
      inputs->vectors.push_back(std::move(v));
    }
  }
  if (inputs->vectors.empty()) inputs->vectors.push_back(base);
  return true;
}

nlohmann::ordered_json FloatToJson(float value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  // The shortest decimal that reads back as the same float, as a JSON number; a fraction
  // part keeps it a floating-point number, so -0 stays -0.0.
  std::string text = FormatFloat(value);
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  return nlohmann::ordered_json::parse(text);
}

std::string FormatFloat(float value) {
  if (std::isnan(value)) return "nan";
  return fmt::format("{}", value);
}

bool SameFloat(float a, float b) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  return std::bit_cast<uint32_t>(a) == std::bit_cast<uint32_t>(b);
}

nlohmann::ordered_json ResultsToJson(const std::vector<VectorResult>& results, bool with_bindings) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const VectorResult& r : results) {
    nlohmann::ordered_json outputs = nlohmann::ordered_json::array();
    for (const OutputRegister& o : r.outputs) {
      nlohmann::ordered_json value = nlohmann::ordered_json::array();
      nlohmann::ordered_json undefined = nlohmann::ordered_json::object();
      static const char kComp[] = "xyzw";
      for (size_t c = 0; c < 4; ++c) {
        value.push_back(FloatToJson(o.value[c]));
        if (!o.undefined[c].empty()) undefined[std::string(1, kComp[c])] = o.undefined[c];
      }
      std::string mask;
      for (size_t c = 0; c < 4; ++c) {
        if (o.written & (1u << c)) mask += kComp[c];
      }
      nlohmann::ordered_json jo = {
          {"register", o.name}, {"value", value}, {"written", mask}, {"undefined", undefined}};
      if (with_bindings) {
        jo["binding"] = {static_cast<int>(o.binding.result), o.binding.index,
                         static_cast<int>(o.binding.face), o.binding.secondary};
      }
      outputs.push_back(std::move(jo));
    }
    out.push_back({{"killed", r.killed}, {"outputs", outputs}});
  }
  return out;
}

bool ResultsFromJson(const nlohmann::json& json, std::vector<VectorResult>* results,
                     std::string* error) {
  results->clear();
  auto bad = [&](std::string_view what) {
    *error = fmt::format("malformed results: {}", what);
    return false;
  };
  if (!json.is_array()) return bad("not a list");
  for (const auto& jr : json) {
    VectorResult r;
    if (!jr.is_object() || !jr.contains("killed") || !jr["killed"].is_boolean() ||
        !jr.contains("outputs") || !jr["outputs"].is_array()) {
      return bad("a vector is {killed, outputs}");
    }
    r.killed = jr["killed"].get<bool>();
    for (const auto& jo : jr["outputs"]) {
      OutputRegister o;
      if (!jo.is_object() || !jo.contains("register") || !jo["register"].is_string() ||
          !jo.contains("value") || !jo["value"].is_array() || jo["value"].size() != 4 ||
          !jo.contains("written") || !jo["written"].is_string()) {
        return bad("an output is {register, value[4], written, undefined}");
      }
      o.name = jo["register"].get<std::string>();
      for (size_t c = 0; c < 4; ++c) {
        if (!JsonFloat(jo["value"][c], &o.value[c])) return bad("a value is not a number");
      }
      for (char ch : jo["written"].get<std::string>()) {
        size_t c = std::string_view("xyzw").find(ch);
        if (c == std::string_view::npos) return bad("written is a mask of xyzw");
        o.written = static_cast<uint8_t>(o.written | (1u << c));
      }
      if (auto it = jo.find("undefined"); it != jo.end() && it->is_object()) {
        for (const auto& [comp, why] : it->items()) {
          size_t c = std::string_view("xyzw").find(comp);
          if (comp.size() != 1 || c == std::string_view::npos || !why.is_string()) {
            return bad("undefined maps x, y, z, w to reasons");
          }
          o.undefined[c] = why.get<std::string>();
        }
      }
      if (auto it = jo.find("binding"); it != jo.end()) {
        const auto& b = *it;
        if (!b.is_array() || b.size() != 4 || !b[0].is_number_integer() ||
            !b[1].is_number_integer() || !b[2].is_number_integer() || !b[3].is_boolean() ||
            b[0].get<int>() < 0 || b[0].get<int>() > static_cast<int>(ResultReg::FragDepth) ||
            b[2].get<int>() < 0 || b[2].get<int>() > 1) {
          return bad("binding is [result, index, face, secondary]");
        }
        o.binding.kind = BindingKind::Result;
        o.binding.result = static_cast<ResultReg>(b[0].get<int>());
        o.binding.index = b[1].get<int32_t>();
        o.binding.face = static_cast<Face>(b[2].get<int>());
        o.binding.secondary = b[3].get<bool>();
      }
      r.outputs.push_back(std::move(o));
    }
    results->push_back(std::move(r));
  }
  return true;
}

std::vector<Difference> CompareResults(const std::vector<VectorResult>& a,
                                       const std::vector<VectorResult>& b) {
  std::vector<Difference> out;
  for (size_t v = 0; v < a.size() && v < b.size(); ++v) {
    const VectorResult& ra = a[v];
    const VectorResult& rb = b[v];
    if (ra.killed != rb.killed) {
      out.push_back({v, "", -1, 0.0f, 0.0f, ra.killed ? "killed by a only" : "killed by b only"});
      continue;
    }
    auto find = [](const VectorResult& r, const std::string& name) -> const OutputRegister* {
      for (const OutputRegister& o : r.outputs) {
        if (o.name == name) return &o;
      }
      return nullptr;
    };
    for (const OutputRegister& oa : ra.outputs) {
      const OutputRegister* ob = find(rb, oa.name);
      if (!ob) {
        out.push_back({v, oa.name, -1, 0.0f, 0.0f, "written by a only"});
        continue;
      }
      for (size_t c = 0; c < 4; ++c) {
        bool both = (oa.written & ob->written & (1u << c)) != 0;
        if (!both || !oa.undefined[c].empty()) continue;
        if (!SameFloat(oa.value[c], ob->value[c])) {
          out.push_back({v, oa.name, static_cast<int>(c), oa.value[c], ob->value[c], ""});
        }
      }
    }
    for (const OutputRegister& ob : rb.outputs) {
      if (!find(ra, ob.name)) out.push_back({v, ob.name, -1, 0.0f, 0.0f, "written by b only"});
    }
  }
  if (a.size() != b.size())
    out.push_back({std::min(a.size(), b.size()), "", -1, 0, 0, "vector counts differ"});
  return out;
}

}  // namespace arbiter::arbvp
