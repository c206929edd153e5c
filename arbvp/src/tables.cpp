// Expansions of the opcode, option and diagnostic tables.
#include <cstdint>
#include <iterator>
#include <string_view>

#include "arbiter/arbvp/check.h"
#include "arbiter/arbvp/ir.h"
#include "diag.h"

namespace arbiter::arbvp {

using compiler::DiagnosticInfo;
using compiler::Severity;

namespace {

// The opcode table as a constant array: GetOpcodeInfo is called for every instruction by
// several checks, and a function-local static costs a guard check per call.
constexpr OpcodeInfo kOpcodeInfos[] = {
#define ARBVP_OPCODE(name, stages, signature, klass, spec) \
  OpcodeInfo{Opcode::name, #name, OpStages::stages, OpSignature::signature, OpClass::klass, spec},
#include "arbiter/arbvp/opcodes.def"
#undef ARBVP_OPCODE
};

// Every ARB opcode name has three characters: a name is looked up as one integer, in a
// switch (one lookup per instruction and per declared name).
constexpr size_t kOpcodeNameSize = 3;
constexpr uint32_t PackOpcodeName(std::string_view name) {
  uint32_t packed = 0;
  for (char c : name) packed = (packed << 8) | static_cast<unsigned char>(c);
  return packed;
}
constexpr bool OpcodeNamesHaveThreeCharacters() {
  for (const OpcodeInfo& info : kOpcodeInfos) {
    if (info.name.size() != kOpcodeNameSize) return false;
  }
  return true;
}
static_assert(OpcodeNamesHaveThreeCharacters());

}  // namespace

const std::vector<OpcodeInfo>& AllOpcodes() {
  static const std::vector<OpcodeInfo> table(std::begin(kOpcodeInfos), std::end(kOpcodeInfos));
  return table;
}

const OpcodeInfo& GetOpcodeInfo(Opcode op) { return kOpcodeInfos[static_cast<size_t>(op)]; }

bool LookupOpcode(std::string_view name, Opcode* op) {
  if (name.size() != kOpcodeNameSize) return false;
  switch (PackOpcodeName(name)) {
#define ARBVP_OPCODE(name, stages, signature, klass, spec) \
  case PackOpcodeName(#name):                              \
    *op = Opcode::name;                                    \
    return true;
#include "arbiter/arbvp/opcodes.def"
#undef ARBVP_OPCODE
    default:
      return false;
  }
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
#define ARBVP_OPTION(name, spelling, stages, group, same_as, spec) \
  OptionInfo{OptionId::name, spelling, OpStages::stages, group, OptionId::same_as, spec},
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
    if (option.id == id || GetOptionInfo(option.id).same_as == id) return true;
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
