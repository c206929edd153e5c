// What the GLSL 1.10 translation refuses (emit.h FindUntranslatable).
#include <fmt/format.h>

#include "arbiter/arbvp/emit.h"

namespace arbiter::arbvp {

Untranslatable FindUntranslatable(const Program& program) {
  for (const Instruction& inst : program.instructions) {
    switch (inst.op) {
      case Opcode::PK2H:
      case Opcode::PK2US:
      case Opcode::PK4B:
      case Opcode::PK4UB:
      case Opcode::UP2H:
      case Opcode::UP2US:
      case Opcode::UP4B:
      case Opcode::UP4UB:
        return {fmt::format("{} needs the bits of a float (floatBitsToUint, GLSL 3.30), which "
                            "GLSL 1.10 cannot form exactly",
                            GetOpcodeInfo(inst.op).name),
                inst.opcode_range};
      default:
        break;
    }
  }
  return {};
}

}  // namespace arbiter::arbvp
