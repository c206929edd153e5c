// Expansions of the opcode, option and diagnostic tables.
#include <algorithm>
#include <cassert>
#include <utility>

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

namespace {

// Every ARB opcode name has three characters (checked when the table is built): a name is
// looked up as one integer, which is cheaper than hashing it (one lookup per instruction).
constexpr size_t kOpcodeNameSize = 3;
uint32_t PackOpcodeName(std::string_view name) {
  uint32_t packed = 0;
  for (char c : name) packed = (packed << 8) | static_cast<unsigned char>(c);
  return packed;
}

}  // namespace

bool LookupOpcode(std::string_view name, Opcode* op) {
  using Entry = std::pair<uint32_t, Opcode>;
  static const std::vector<Entry> by_name = [] {
    std::vector<Entry> entries;
    for (const OpcodeInfo& info : AllOpcodes()) {
      assert(info.name.size() == kOpcodeNameSize);
      entries.emplace_back(PackOpcodeName(info.name), info.op);
    }
    std::sort(entries.begin(), entries.end());
    return entries;
  }();
  if (name.size() != kOpcodeNameSize) return false;
  uint32_t key = PackOpcodeName(name);
  auto it = std::lower_bound(by_name.begin(), by_name.end(), key,
                             [](const Entry& e, uint32_t k) { return e.first < k; });
  if (it == by_name.end() || it->first != key) return false;
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
