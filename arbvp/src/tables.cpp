// Expansions of the opcode, option and diagnostic tables.
#include <cassert>
#include <unordered_map>

#include "arbiter/arbvp/check.h"
#include "arbiter/arbvp/ir.h"
#include "diag.h"

namespace arbiter::arbvp {

using compiler::DiagnosticInfo;
using compiler::Severity;

const std::vector<OpcodeInfo>& AllOpcodes() {
  static const std::vector<OpcodeInfo> table = {
#define ARBVP_OPCODE(name, stages, signature, klass, spec) \
  OpcodeInfo{Opcode::name, #name, OpStages::stages, OpSignature::signature, OpClass::klass, spec},
#include "arbiter/arbvp/opcodes.def"
#undef ARBVP_OPCODE
  };
  return table;
}

const OpcodeInfo& GetOpcodeInfo(Opcode op) { return AllOpcodes()[static_cast<size_t>(op)]; }

bool LookupOpcode(std::string_view name, Opcode* op) {
  static const std::unordered_map<std::string_view, Opcode> by_name = [] {
    std::unordered_map<std::string_view, Opcode> map;
    for (const OpcodeInfo& info : AllOpcodes()) map.emplace(info.name, info.op);
    return map;
  }();
  auto it = by_name.find(name);
  if (it == by_name.end()) return false;
  *op = it->second;
  return true;
}

bool OpcodeInStage(Opcode op, ProgramKind kind) {
  auto stages = static_cast<unsigned>(GetOpcodeInfo(op).stages);
  return (stages & (kind == ProgramKind::Vertex ? 1u : 2u)) != 0;
}

int SourceCount(OpSignature signature) {
  switch (signature) {
    case OpSignature::Vector:
    case OpSignature::Scalar:
    case OpSignature::Swz:
    case OpSignature::Arl:
    case OpSignature::Sample:
    case OpSignature::Kil:
      return 1;
    case OpSignature::BinSc:
    case OpSignature::Binary:
      return 2;
    case OpSignature::Ternary:
      return 3;
  }
  return 0;
}

const std::vector<OptionInfo>& AllOptions() {
  static const std::vector<OptionInfo> table = {
#define ARBVP_OPTION(name, spelling, stages, group, spec) \
  OptionInfo{OptionId::name, spelling, OpStages::stages, group, spec},
#include "arbiter/arbvp/options.def"
#undef ARBVP_OPTION
  };
  return table;
}

const OptionInfo& GetOptionInfo(OptionId id) { return AllOptions()[static_cast<size_t>(id)]; }

bool LookupOption(std::string_view spelling, OptionId* id) {
  for (const OptionInfo& info : AllOptions()) {
    if (info.spelling == spelling) {
      *id = info.id;
      return true;
    }
  }
  return false;
}

bool Program::HasOption(OptionId id) const {
  for (const Option& option : options) {
    if (option.id == id) return true;
  }
  return false;
}

std::string_view TexTargetName(TexTarget target) {
  switch (target) {
    case TexTarget::Tex1D:
      return "1D";
    case TexTarget::Tex2D:
      return "2D";
    case TexTarget::Tex3D:
      return "3D";
    case TexTarget::Cube:
      return "CUBE";
    case TexTarget::Rect:
      return "RECT";
    case TexTarget::Shadow1D:
      return "SHADOW1D";
    case TexTarget::Shadow2D:
      return "SHADOW2D";
    case TexTarget::ShadowRect:
      return "SHADOWRECT";
  }
  return "?";
}

namespace {
const DiagnosticInfo kDiagInfos[] = {
#define ARBVP_DIAG(name, code, severity, summary, spec) \
  DiagnosticInfo{code, Severity::severity, summary, spec},
#include "diagnostics.def"
#undef ARBVP_DIAG
};
}  // namespace

const DiagnosticInfo& Info(Diag diag) { return kDiagInfos[static_cast<size_t>(diag)]; }

const std::vector<const DiagnosticInfo*>& AllDiagnostics() {
  static const std::vector<const DiagnosticInfo*> all = [] {
    std::vector<const DiagnosticInfo*> list;
    for (const DiagnosticInfo& info : kDiagInfos) list.push_back(&info);
    return list;
  }();
  return all;
}

}  // namespace arbiter::arbvp
