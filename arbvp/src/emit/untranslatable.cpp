// What the GLSL 1.10 translation refuses (emit.h FindUntranslatable).
#include <fmt/format.h>

#include <algorithm>
#include <iterator>

#include "arbiter/arbvp/emit.h"

namespace arbiter::arbvp {

namespace {

// The NV pack and unpack instructions: they form or read the bits of a float.
constexpr Opcode kNeedFloatBits[] = {Opcode::PK2H, Opcode::PK2US, Opcode::PK4B, Opcode::PK4UB,
                                     Opcode::UP2H, Opcode::UP2US, Opcode::UP4B, Opcode::UP4UB};

}  // namespace

Untranslatable FindUntranslatable(const Program& program) {
  for (const Instruction& inst : program.instructions) {
    if (std::find(std::begin(kNeedFloatBits), std::end(kNeedFloatBits), inst.op) ==
        std::end(kNeedFloatBits)) {
      continue;
    }
    return {fmt::format("{} needs the bits of a float (floatBitsToUint, GLSL 3.30), which GLSL "
                        "1.10 cannot form exactly",
                        GetOpcodeInfo(inst.op).name),
            inst.opcode_range};
  }
  return {};
}

}  // namespace arbiter::arbvp
