// Comparing a Mesa engine's results with the reference interpreter's under the tolerance
// model: undefined components, unstable ones and known deviations are left out.
#include <cmath>

#include "arbiter/arbvp/deviations.h"
#include "arbiter/runtime/verify.h"

namespace arbiter::runtime {
namespace {

const arbvp::OutputRegister* Find(const arbvp::VectorResult& r, const std::string& name) {
  for (const arbvp::OutputRegister& o : r.outputs) {
    if (o.name == name) return &o;
  }
  return nullptr;
}

// Whether `got` is within `tolerance` of the reference `want`: NaN for NaN, the same
// infinity for an infinity, otherwise |got - want| <= tolerance (so -0 matches +0).
bool WithinTolerance(float got, float want, float tolerance) {
  if (std::isnan(want)) return std::isnan(got);
  if (std::isinf(want)) return got == want;
  if (!std::isfinite(got)) return false;
  double d = std::fabs(static_cast<double>(got) - static_cast<double>(want));
  return d <= static_cast<double>(tolerance);
}

std::string DeviationName(uint32_t bits) {
  for (const arbvp::DeviationInfo& d : arbvp::KnownDeviations()) {
    if (bits & d.bit) return std::string(d.name);
  }
  return "unknown";
}

// Adds a disagreement of `engine`, merged with another engine's at the same place.
void Record(Disagreement d, const std::string& engine, float value, Verdict* verdict) {
  for (Disagreement& e : verdict->disagreements) {
    if (e.batch == d.batch && e.vector == d.vector && e.reg == d.reg &&
        e.component == d.component && e.what.empty() == d.what.empty()) {
      e.engines.push_back(engine);
      e.values[engine] = value;
      if (e.what != d.what && !d.what.empty()) e.what += "; " + d.what;
      return;
    }
  }
  d.engines.push_back(engine);
  d.values[engine] = value;
  verdict->disagreements.push_back(std::move(d));
}

}  // namespace

void CompareWithReference(const std::vector<arbvp::VectorResult>& ref,
                          const std::vector<arbvp::VectorResult>& engine, const std::string& name,
                          uint32_t applicable, const std::string& batch, Verdict* verdict) {
  for (size_t v = 0; v < ref.size() && v < engine.size(); ++v) {
    const arbvp::VectorResult& r = ref[v];
    const arbvp::VectorResult& e = engine[v];
    if (r.kill_unstable || !r.kill_undefined.empty()) continue;
    if (r.killed != e.killed) {
      if (r.kill_deviations & applicable) {
        verdict->deviations[DeviationName(r.kill_deviations & applicable)] += 1;
        continue;
      }
      Disagreement d;
      d.batch = batch;
      d.vector = v;
      d.what = r.killed ? "killed by ref, not by " + name : "killed by " + name + ", not by ref";
      Record(std::move(d), name, 0.0f, verdict);
      continue;
    }
    if (r.killed) continue;
    for (const arbvp::OutputRegister& o : r.outputs) {
      const arbvp::OutputRegister* g = Find(e, o.name);
      if (!g) {
        Disagreement d;
        d.batch = batch;
        d.vector = v;
        d.reg = o.name;
        d.what = "not written by " + name;
        Record(std::move(d), name, 0.0f, verdict);
        continue;
      }
      for (size_t c = 0; c < 4; ++c) {
        uint8_t bit = static_cast<uint8_t>(1u << c);
        // mesa-glsl reports only what GLSL can express (x of result.fogcoord...).
        if (!(o.written & bit) || !(g->written & bit)) continue;
        if (!o.undefined[c].empty() || std::isinf(o.tolerance[c])) continue;
        if (o.deviations[c] & applicable) {
          verdict->deviations[DeviationName(o.deviations[c] & applicable)] += 1;
          continue;
        }
        verdict->compared += 1;
        if (WithinTolerance(g->value[c], o.value[c], o.tolerance[c])) continue;
        Disagreement d;
        d.batch = batch;
        d.vector = v;
        d.reg = o.name;
        d.component = static_cast<int>(c);
        d.tolerance = o.tolerance[c];
        d.values[kEngineRef] = o.value[c];
        Record(std::move(d), name, g->value[c], verdict);
      }
    }
  }
}

}  // namespace arbiter::runtime
