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
    nlohmann::ordered_json e{
        {"binding", r.binding}, {"glsl", r.glsl}, {"stage", StageName(r.stage)}};
    if (r.location >= 0) e["location"] = r.location;
    out.push_back(e);
  }
  return out;
}

}  // namespace

std::string BindingMapToJson(const BindingMap& map) {
  nlohmann::ordered_json j;
  // The keys of the other targets only where they differ from GLSL 1.10's built-in state, so
  // that the GLSL 1.10 maps stay as they were (docs/json-output.md, docs/guide/translate.md "State
  // as uniforms").
  if (map.target != "glsl110" || map.state_uniforms) {
    j["target"] = map.target;
    j["state_source"] = map.state_uniforms ? "uniforms" : "builtins";
  }
  if (!map.blocks.empty()) {
    j["blocks"] = nlohmann::ordered_json::array();
    for (const UniformBlock& b : map.blocks) {
      j["blocks"].push_back({{"name", b.name},
                             {"stage", StageName(b.stage)},
                             {"layout", "std140"},
                             {"set", b.set},
                             {"binding", b.binding},
                             {"size", b.size}});
    }
  }
  j["attributes"] = nlohmann::ordered_json::array();
  for (const AttributeBinding& a : map.attributes) {
    nlohmann::ordered_json e{{"name", a.name}};
    e["location"] = a.location >= 0 ? nlohmann::ordered_json(a.location) : nullptr;
    e["binding"] = a.binding;
    j["attributes"].push_back(e);
  }
  j["parameters"] = nlohmann::ordered_json::array();
  for (const ParameterArray& p : map.parameters) {
    nlohmann::ordered_json e{{"name", p.name},
                             {"target", StageName(p.target)},
                             {"kind", p.local ? "local" : "env"},
                             {"size", p.size}};
    if (p.offset >= 0) {
      e["block"] = p.target == ProgramKind::Vertex ? "ArbVertexUniforms" : "ArbFragmentUniforms";
      e["offset"] = p.offset;
    }
    j["parameters"].push_back(e);
  }
  j["samplers"] = nlohmann::ordered_json::array();
  for (const SamplerBinding& s : map.samplers) {
    nlohmann::ordered_json e{
        {"name", s.name}, {"unit", s.unit}, {"target", TexTargetName(s.target)}, {"type", s.type}};
    if (s.binding >= 0) {
      e["set"] = 0;
      e["binding"] = s.binding;
    }
    j["samplers"].push_back(e);
  }
  j["state"] = nlohmann::ordered_json::array();
  for (const StateUniform& s : map.state) {
    nlohmann::ordered_json e{{"name", s.name}, {"type", s.type}, {"binding", s.binding}};
    if (s.offset >= 0) {
      e["block"] = s.block;
      e["offset"] = s.offset;
    }
    j["state"].push_back(e);
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
