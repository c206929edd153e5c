// UnusedInputWarnings (exec_io.h): what `arbiter exec` is given that its programs never read.
#include <fmt/format.h>

#include <algorithm>
#include <set>
#include <string>

#include "arbiter/arbvp/exec_io.h"

namespace arbiter::arbvp {
namespace {

// One spelling per input: "vertex.texcoord" is texcoord[0] and "fragment.color" the primary
// colour, as the ARB grammar reads them.
std::string Canonical(std::string name) {
  for (std::string_view unindexed : {"vertex.texcoord", "fragment.texcoord"}) {
    if (name == unindexed) name += "[0]";
  }
  constexpr std::string_view kPrimary = ".primary";
  if (name.size() > kPrimary.size() &&
      name.compare(name.size() - kPrimary.size(), kPrimary.size(), kPrimary) == 0) {
    name.resize(name.size() - kPrimary.size());
  }
  return name;
}

// What the programs read: attribute bindings by name (only those of the program that gets
// them: in a pair, fragment.* comes from the vertex program), program.env and program.local
// entries per target ("vertex.program.env[2]"), and the sampled units with their targets.
struct Reads {
  std::set<std::string> attributes;
  std::set<std::string> parameters;
  std::map<int, std::set<TexDim>> units;
};

Reads ReadsOf(const std::vector<const Program*>& programs) {
  Reads reads;
  const bool pair = programs.size() > 1;
  for (const Program* p : programs) {
    const std::string_view target = p->kind == ProgramKind::Vertex ? "vertex" : "fragment";
    for (const Variable& v : p->vars) {
      for (const Binding& b : v.bindings) {
        if (b.kind == BindingKind::ProgramEnv || b.kind == BindingKind::ProgramLocal) {
          reads.parameters.insert(fmt::format("{}.program.{}[{}]", target,
                                              b.kind == BindingKind::ProgramEnv ? "env" : "local",
                                              b.index));
        } else if (v.kind == VarKind::Attrib && !(pair && p->kind == ProgramKind::Fragment)) {
          reads.attributes.insert(Canonical(BindingName(b, p->kind)));
        }
      }
    }
    for (const Instruction& inst : p->instructions) {
      if (GetOpcodeInfo(inst.op).signature == OpSignature::Sample) {
        reads.units[inst.tex_unit].insert(TargetDim(inst.target));
      }
    }
  }
  return reads;
}

}  // namespace

std::vector<std::string> UnusedInputWarnings(const std::vector<const Program*>& programs,
                                             const std::vector<std::string>& assignments,
                                             const ExecInputs& inputs) {
  const Reads reads = ReadsOf(programs);
  std::vector<std::string> warnings;
  for (const std::string& assignment : assignments) {
    const std::string name = Canonical(assignment.substr(0, assignment.find('=')));
    // Derived state reads state indirectly; fragment.depth places the fragment (its window
    // z), whatever the program reads.
    if (name.rfind("state.", 0) == 0 || name == "fragment.depth") continue;
    bool read = false;
    if (name.rfind("program.", 0) == 0) {  // both targets
      read = reads.parameters.count("vertex." + name) > 0 ||
             reads.parameters.count("fragment." + name) > 0;
    } else if (name.find(".program.") != std::string::npos) {
      read = reads.parameters.count(name) > 0;
    } else {
      read = reads.attributes.count(name) > 0;
    }
    if (!read) {
      warnings.push_back(
          fmt::format("--set {}: no program of this run reads {}", assignment, name));
    }
  }
  for (const auto& [unit, texture] : inputs.textures) {
    auto sampled = reads.units.find(unit);
    if (sampled == reads.units.end()) {
      warnings.push_back(fmt::format("texture unit {}: no instruction samples it", unit));
    } else if (sampled->second.count(texture.dim) == 0) {
      warnings.push_back(fmt::format(
          "texture unit {}: a {} texture, but the program samples it as {}: it reads GL's "
          "incomplete texture",
          unit, TexDimName(texture.dim), TexDimName(*sampled->second.begin())));
    }
  }
  for (const auto& [unit, dims] : reads.units) {
    if (inputs.textures.count(unit) == 0) {
      warnings.push_back(fmt::format(
          "texture unit {} is sampled ({}) but given no texture (--texture {}={}:checker): it "
          "reads GL's incomplete texture",
          unit, TexDimName(*dims.begin()), unit, TexDimName(*dims.begin())));
    }
  }
  return warnings;
}

}  // namespace arbiter::arbvp
