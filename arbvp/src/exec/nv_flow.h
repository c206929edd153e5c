// The machine state the NV program options add to a run, and the instructions that change
// it rather than a register: condition codes, branches and subroutines
// (NV_vertex_program2_option 2.14.4.X, NV_fragment_program2 3.11.4.X), the address stack
// of NV_vertex_program3 (PUSHA, POPA), IF/ELSE/ENDIF, LOOP/ENDLOOP and REP/ENDREP blocks,
// and the bound on executed instructions.
#pragma once

#include <string>
#include <vector>

#include "arbiter/arbvp/ir.h"
#include "exec/cond_codes.h"
#include "exec/machine.h"

namespace arbiter::arbvp::exec {

// The minimums of the implementation-dependent limits (NV_fragment_program2's table,
// NV_vertex_program2 2.14.4.X): a program that goes past one behaves as the implementation
// decides, so its results are undefined.
inline constexpr int kMaxExecInstructions = 65536;  // MAX_PROGRAM_EXEC_INSTRUCTIONS_NV
inline constexpr size_t kMaxCallDepth = 4;          // MAX_PROGRAM_CALL_DEPTH_NV
inline constexpr size_t kMaxIfDepth = 48;           // MAX_PROGRAM_IF_DEPTH_NV
inline constexpr size_t kMaxLoopDepth = 4;          // MAX_PROGRAM_LOOP_DEPTH_NV
inline constexpr float kMaxLoopCount = 255.0f;      // MAX_PROGRAM_LOOP_COUNT_NV

class NvMachine {
 public:
  NvMachine(const Program& program, Reasons* reasons);

  // The first instruction: the one after the label "main", else the first.
  int Entry() const;
  CcReg& cc(int reg) { return cc_[static_cast<size_t>(reg)]; }
  // A condition of BRA, CAL, RET, BRK, IF or KIL <ccTest>; an uncertain outcome taints the
  // run (the caller decides on the outcome's `pass`).
  CcOutcome Condition(const CcTest& test);

  // Counts the instruction about to execute; false once MAX_PROGRAM_EXEC_INSTRUCTIONS_NV
  // have run (the program terminates abnormally).
  bool Count(const std::string& where);

  // Runs a flow instruction (OpClass::Flow) at *pc with its loaded operand (LOOP, REP) and
  // sets *pc to the next instruction; false when the program terminates.
  bool Step(const Instruction& inst, const Reg& operand, int* pc, const std::string& where);
  // PUSHA and POPA: false when the program terminates (overflow, underflow, or a return
  // address on top for POPA).
  bool Push(const Reg& address, const std::string& where);
  bool Pop(Reg* address, const std::string& where);

  // The loop index A0.x of the innermost LOOP block, clamped to >= 0; false outside one.
  bool LoopIndex(Val* index) const;

  const Taint& taint() const { return taint_; }

 private:
  struct Frame {
    int return_pc = -1;  // CAL: the instruction after it; -1 for a PUSHA entry
    size_t blocks = 0;   // CAL: the active blocks then (RET leaves the callee's)
    Reg address{};       // PUSHA: the pushed register
  };
  struct Block {
    Opcode op = Opcode::IF;
    int begin = 0;  // LOOP / REP: its index
    float count = 0.0f;
    Val index;
    float increment = 0.0f;
  };

  bool Terminate(const std::string& what, const std::string& where);
  bool EnterLoop(const Instruction& inst, const Reg& operand, int* pc, const std::string& where);
  size_t Depth(bool loops) const;

  const Program& program_;
  Reasons* reasons_;
  std::array<CcReg, 2> cc_{};
  std::vector<Frame> stack_;
  std::vector<Block> blocks_;
  int executed_ = 0;
  Taint taint_;
};

}  // namespace arbiter::arbvp::exec
