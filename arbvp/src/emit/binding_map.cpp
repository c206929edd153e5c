// The binding map as JSON (stable key order) for `arbiter translate --bindings` and tests.
#include <nlohmann/json.hpp>

#include "arbiter/arbvp/emit.h"

namespace arbiter::arbvp {
namespace {

std::string_view StageName(ProgramKind kind) {
  return kind == ProgramKind::Vertex ? "vertex" : "fragment";
}

nlohmann::ordered_json Registers(const std::vector<RegisterMapping>& registers) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const RegisterMapping& r : registers) {
    out.push_back({{"binding", r.binding}, {"glsl", r.glsl}, {"stage", StageName(r.stage)}});
  }
  return out;
}

}  // namespace

std::string BindingMapToJson(const BindingMap& map) {
  nlohmann::ordered_json j;
  j["attributes"] = nlohmann::ordered_json::array();
  for (const AttributeBinding& a : map.attributes) {
    nlohmann::ordered_json e{{"name", a.name}};
    e["location"] = a.location >= 0 ? nlohmann::ordered_json(a.location) : nullptr;
    e["binding"] = a.binding;
    j["attributes"].push_back(e);
  }
  j["parameters"] = nlohmann::ordered_json::array();
  for (const ParameterArray& p : map.parameters) {
    j["parameters"].push_back({{"name", p.name},
                               {"target", StageName(p.target)},
                               {"kind", p.local ? "local" : "env"},
                               {"size", p.size}});
  }
  j["samplers"] = nlohmann::ordered_json::array();
  for (const SamplerBinding& s : map.samplers) {
    j["samplers"].push_back({{"name", s.name},
                             {"unit", s.unit},
                             {"target", TexTargetName(s.target)},
                             {"type", s.type}});
  }
  j["state"] = nlohmann::ordered_json::array();
  for (const StateUniform& s : map.state) {
    j["state"].push_back({{"name", s.name}, {"type", s.type}, {"binding", s.binding}});
  }
  j["inputs"] = Registers(map.inputs);
  j["outputs"] = Registers(map.outputs);
  j["undefined"] = {
      {"relative_out_of_range", map.relative_out_of_range_reads_zero ? "vec4(0.0)" : "undefined"},
      {"xpd_w", map.xpd_w},
      {"scs_zw", {map.scs_z, map.scs_w}},
      {"temporaries_initial", map.temporaries_start_zero ? "vec4(0.0)" : "undefined"}};
  j["mutation"] = map.mutation;
  return j.dump(2) + "\n";
}

}  // namespace arbiter::arbvp
