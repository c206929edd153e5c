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
#define ARBVP_OPCODE(name, vp, fp, signature, klass, vp_mods, fp_mods, fp2_mods, reads, spec) \
  OpcodeInfo{Opcode::name,                                                                    \
             #name,                                                                           \
             OpLevel::vp,                                                                     \
             OpLevel::fp,                                                                     \
             OpSignature::signature,                                                          \
             OpClass::klass,                                                                  \
             vp_mods,                                                                         \
             fp_mods,                                                                         \
             fp2_mods,                                                                        \
             reads,                                                                           \
             spec},
#include "arbiter/arbvp/opcodes.def"
#undef ARBVP_OPCODE
};

// Opcode names have at most eight characters ("ENDLOOP"): a name is looked up as one
// integer, in a switch (one lookup per instruction and per declared name).
constexpr size_t kMaxOpcodeName = 8;
constexpr uint64_t PackOpcodeName(std::string_view name) {
  uint64_t packed = 0;
  for (char c : name) packed = (packed << 8) | static_cast<unsigned char>(c);
  return packed;
}
constexpr bool OpcodeNamesFit() {
  for (const OpcodeInfo& info : kOpcodeInfos) {
    if (info.name.size() > kMaxOpcodeName) return false;
  }
  return true;
}
static_assert(OpcodeNamesFit());

}  // namespace

const std::vector<OpcodeInfo>& AllOpcodes() {
  static const std::vector<OpcodeInfo> table(std::begin(kOpcodeInfos), std::end(kOpcodeInfos));
  return table;
}

const OpcodeInfo& GetOpcodeInfo(Opcode op) { return kOpcodeInfos[static_cast<size_t>(op)]; }

bool LookupOpcode(std::string_view name, Opcode* op) {
  if (name.size() < 2 || name.size() > kMaxOpcodeName) return false;
  switch (PackOpcodeName(name)) {
#define ARBVP_OPCODE(name, vp, fp, signature, klass, vp_mods, fp_mods, fp2_mods, reads, spec) \
  case PackOpcodeName(#name):                                                                 \
    *op = Opcode::name;                                                                       \
    return true;
#include "arbiter/arbvp/opcodes.def"
#undef ARBVP_OPCODE
    default:
      return false;
  }
}

OpLevel OpcodeLevel(Opcode op, ProgramKind kind) {
  const OpcodeInfo& info = GetOpcodeInfo(op);
  return kind == ProgramKind::Vertex ? info.vp : info.fp;
}

bool OpcodeInStage(Opcode op, ProgramKind kind) { return OpcodeLevel(op, kind) == OpLevel::Arb; }

int SourceCount(OpSignature signature) {
  switch (signature) {
    case OpSignature::Vector:
    case OpSignature::Scalar:
    case OpSignature::Swz:
    case OpSignature::Arl:
    case OpSignature::Sample:
    case OpSignature::Kil:  // the <ccTest> form has none
    case OpSignature::Ara:
    case OpSignature::Arr:
    case OpSignature::PushA:
    case OpSignature::Loop:
      return 1;
    case OpSignature::BinSc:
    case OpSignature::Binary:
    case OpSignature::VecSca:
      return 2;
    case OpSignature::Ternary:
    case OpSignature::TexD:
      return 3;
    case OpSignature::PopA:
    case OpSignature::Branch:
    case OpSignature::FlowCc:
    case OpSignature::If:
    case OpSignature::EndFlow:
      return 0;
  }
  return 0;
}

const std::vector<OptionInfo>& AllOptions() {
  static const std::vector<OptionInfo> table = {
#define ARBVP_OPTION(name, spelling, stages, group, implies, spec) \
  OptionInfo{OptionId::name, spelling, OpStages::stages, group, OptionId::implies, spec},
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

int Program::NvLevel() const {
  if (HasOption(OptionId::NvVertexProgram3) || HasOption(OptionId::NvFragmentProgram2)) return 2;
  if (HasOption(OptionId::NvVertexProgram2) || HasOption(OptionId::NvFragmentProgram)) return 1;
  return 0;
}

bool Program::HasOpcode(Opcode op) const {
  switch (OpcodeLevel(op, kind)) {
    case OpLevel::No:
      return false;
    case OpLevel::Arb:
      return true;
    case OpLevel::Nv:
      return NvLevel() >= 1;
    case OpLevel::Nv2:
      return NvLevel() >= 2;
  }
  return false;
}

bool Program::HasOption(OptionId id) const {
  for (const Option& option : options) {
    if (option.id == id || GetOptionInfo(option.id).implies == id) return true;
  }
  return false;
}

namespace {
struct TexTargetInfo {
  std::string_view spelling;
  uint8_t coords;
  bool shadow;
};
constexpr TexTargetInfo kTexTargets[] = {
#define ARBVP_TEX_TARGET(name, spelling, coords, shadow, ...) {spelling, coords, shadow},
#include "arbiter/arbvp/texture_targets.def"
#undef ARBVP_TEX_TARGET
};
const TexTargetInfo& Info(TexTarget target) { return kTexTargets[static_cast<size_t>(target)]; }
}  // namespace

std::string_view TexTargetName(TexTarget target) { return Info(target).spelling; }
uint8_t TexTargetCoordMask(TexTarget target) { return Info(target).coords; }
bool TexTargetIsShadow(TexTarget target) { return Info(target).shadow; }

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
