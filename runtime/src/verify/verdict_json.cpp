// VerdictToJson / VerdictFromJson: see verdict_json.h.
#include "verify/verdict_json.h"

#include <bit>
#include <cstdint>

namespace arbiter::runtime {
namespace {

uint32_t Bits(float value) { return std::bit_cast<uint32_t>(value); }
float FromBits(uint32_t bits) { return std::bit_cast<float>(bits); }

nlohmann::json DisagreementToJson(const Disagreement& d) {
  nlohmann::json values = nlohmann::json::object();
  for (const auto& [engine, value] : d.values) values[engine] = Bits(value);
  return {{"batch", d.batch},
          {"vector", d.vector},
          {"reg", d.reg},
          {"component", d.component},
          {"label", d.label},
          {"what", d.what},
          {"tolerance", Bits(d.tolerance)},
          {"values", values},
          {"engines", d.engines},
          {"inputs", d.inputs}};
}

Disagreement DisagreementFromJson(const nlohmann::json& j) {
  Disagreement d;
  d.batch = j.at("batch").get<std::string>();
  d.vector = j.at("vector").get<size_t>();
  d.reg = j.at("reg").get<std::string>();
  d.component = j.at("component").get<int>();
  d.label = j.at("label").get<std::string>();
  d.what = j.at("what").get<std::string>();
  d.tolerance = FromBits(j.at("tolerance").get<uint32_t>());
  for (const auto& [engine, value] : j.at("values").items()) {
    d.values[engine] = FromBits(value.get<uint32_t>());
  }
  d.engines = j.at("engines").get<std::vector<std::string>>();
  d.inputs = j.at("inputs").get<std::vector<std::string>>();
  return d;
}

}  // namespace

nlohmann::json VerdictToJson(const Verdict& v) {
  nlohmann::json disagreements = nlohmann::json::array();
  for (const Disagreement& d : v.disagreements) disagreements.push_back(DisagreementToJson(d));
  return {{"name", v.name},
          {"error", v.error},
          {"vectors", v.vectors},
          {"compared", v.compared},
          {"undefined", v.undefined},
          {"unstable", v.unstable},
          {"deviations", v.deviations},
          {"disagreements", std::move(disagreements)},
          {"not_applicable", v.not_applicable}};
}

bool VerdictFromJson(const nlohmann::json& j, Verdict* v) {
  try {
    v->name = j.at("name").get<std::string>();
    v->error = j.at("error").get<std::string>();
    v->vectors = j.at("vectors").get<size_t>();
    v->compared = j.at("compared").get<size_t>();
    v->undefined = j.at("undefined").get<std::map<std::string, size_t>>();
    v->unstable = j.at("unstable").get<size_t>();
    v->deviations = j.at("deviations").get<std::map<std::string, size_t>>();
    v->not_applicable = j.at("not_applicable").get<std::map<std::string, std::string>>();
    v->disagreements.clear();
    for (const nlohmann::json& d : j.at("disagreements")) {
      v->disagreements.push_back(DisagreementFromJson(d));
    }
  } catch (const nlohmann::json::exception&) {
    return false;
  }
  return true;
}

}  // namespace arbiter::runtime
