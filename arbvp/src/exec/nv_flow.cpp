// Flow control of the NV options (nv_flow.h): the pseudo-code of BRA, CAL, RET
// (NV_vertex_program2_option 2.14.5.30-34, NV_vertex_program3's RET), PUSHA, POPA
// (NV_vertex_program3 2.14.5.43-44), BRK, ELSE, ENDIF, ENDLOOP, ENDREP, IF, LOOP, REP
// (NV_fragment_program2 3.11.X).
#include "exec/nv_flow.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace arbiter::arbvp::exec {

NvMachine::NvMachine(const Program& program, Reasons* reasons)
    : program_(program), reasons_(reasons) {}

int NvMachine::Entry() const {
  for (const Label& label : program_.labels) {
    if (label.name == "main") return label.index;
  }
  return 0;
}

CcOutcome NvMachine::Condition(const CcTest& test) {
  CcOutcome o = TestCcAny(test, cc(test.reg));
  if (!o.certain() || o.dev != 0) taint_.Add(o.why, o.unstable, o.dev);
  return o;
}

bool NvMachine::Count(const std::string& where) {
  if (++executed_ <= kMaxExecInstructions) return true;
  return Terminate(fmt::format("the program ran past MAX_PROGRAM_EXEC_INSTRUCTIONS_NV ({}) and "
                               "terminated",
                               kMaxExecInstructions),
                   where);
}

// An abnormal termination: "all of the vertex program results are undefined"; a fragment
// program's are the values it had, at a point the implementation's limits choose.
bool NvMachine::Terminate(const std::string& what, const std::string& where) {
  taint_.Add(reasons_->Add(what + where), false, 0);
  return false;
}

size_t NvMachine::Depth(bool loops) const {
  return static_cast<size_t>(std::count_if(blocks_.begin(), blocks_.end(), [&](const Block& b) {
    return (b.op != Opcode::IF) == loops;
  }));
}

bool NvMachine::Step(const Instruction& inst, const Reg& operand, int* pc,
                     const std::string& where) {
  const int next = *pc + 1;
  *pc = next;
  switch (inst.op) {
    case Opcode::BRA:
      if (Condition(inst.cond).pass) *pc = inst.jump;
      return true;
    case Opcode::CAL:
      if (!Condition(inst.cond).pass) return true;
      if (stack_.size() >= kMaxCallDepth) {
        return Terminate(fmt::format("CAL beyond MAX_PROGRAM_CALL_DEPTH_NV ({}) overflowed the "
                                     "call stack",
                                     kMaxCallDepth),
                         where);
      }
      stack_.push_back({next, blocks_.size(), {}});
      *pc = inst.jump;
      return true;
    case Opcode::RET: {
      if (!Condition(inst.cond).pass) return true;
      if (stack_.empty()) return false;  // a normal termination
      const Frame top = stack_.back();
      stack_.pop_back();
      if (top.return_pc < 0) {
        return Terminate("RET found an address register pushed by PUSHA on the call stack", where);
      }
      blocks_.resize(std::min(blocks_.size(), top.blocks));
      *pc = top.return_pc;
      return true;
    }
    case Opcode::BRK:
      if (!Condition(inst.cond).pass) return true;
      while (!blocks_.empty()) {
        const bool loop = blocks_.back().op != Opcode::IF;
        blocks_.pop_back();
        if (loop) break;
      }
      *pc = inst.jump + 1;
      return true;
    case Opcode::IF: {
      if (Depth(false) >= kMaxIfDepth) {
        return Terminate(
            fmt::format("IF nested beyond MAX_PROGRAM_IF_DEPTH_NV ({}) at run time", kMaxIfDepth),
            where);
      }
      const bool pass = Condition(inst.cond).pass;
      const bool has_else =
          inst.jump >= 0 && static_cast<size_t>(inst.jump) < program_.instructions.size() &&
          program_.instructions[static_cast<size_t>(inst.jump)].op == Opcode::ELSE;
      // The block is active in the "true" part, and in the ELSE part when it has one.
      if (pass || has_else) {
        Block b;
        b.begin = *pc - 1;
        blocks_.push_back(b);
      }
      if (!pass) *pc = inst.jump + 1;
      return true;
    }
    case Opcode::ELSE:
      *pc = inst.jump;  // the end of the "true" part: on to the ENDIF, which closes the block
      return true;
    case Opcode::ENDIF:
      if (!blocks_.empty() && blocks_.back().op == Opcode::IF) blocks_.pop_back();
      return true;
    case Opcode::LOOP:
    case Opcode::REP:
      return EnterLoop(inst, operand, pc, where);
    case Opcode::ENDLOOP:
    case Opcode::ENDREP: {
      if (blocks_.empty() || blocks_.back().op == Opcode::IF) return true;
      Block& b = blocks_.back();
      b.count -= 1.0f;
      b.index.v += b.increment;
      if (b.count > 0.0f) {
        *pc = b.begin + 1;
      } else {
        blocks_.pop_back();
      }
      return true;
    }
    default:
      break;
  }
  return true;
}

// LOOP and REP: count = floor(op0.x) (LOOP: index = floor(op0.y), increment = floor(op0.z));
// a count that is not positive skips the block.
bool NvMachine::EnterLoop(const Instruction& inst, const Reg& operand, int* pc,
                          const std::string& where) {
  const std::string_view name = inst.op == Opcode::LOOP ? "LOOP" : "REP";
  if (Depth(true) >= kMaxLoopDepth) {
    return Terminate(fmt::format("{} nested beyond MAX_PROGRAM_LOOP_DEPTH_NV ({}) at run time",
                                 name, kMaxLoopDepth),
                     where);
  }
  const bool loop = inst.op == Opcode::LOOP;
  const size_t used = loop ? 3 : 1;
  for (size_t i = 0; i < used; ++i) {
    const Val& v = operand[i];
    const bool floor_moves =
        std::isinf(v.err) || std::floor(v.v - v.err) != std::floor(v.v + v.err);
    if (v.why != kDefined || floor_moves || v.dev != 0) taint_.Add(v.why, floor_moves, v.dev);
    if (!std::isfinite(v.v)) {
      return Terminate(fmt::format("{} with an infinite or NaN operand", name), where);
    }
  }
  Block b;
  b.op = inst.op;
  b.begin = *pc - 1;
  b.count = std::floor(operand[0].v);
  if (loop) {
    b.index = operand[1];
    b.index.v = std::floor(operand[1].v);
    b.index.err = 0.0f;
    b.increment = std::floor(operand[2].v);
  }
  if (b.count > kMaxLoopCount) {
    taint_.Add(reasons_->Add(fmt::format("{} count {} above MAX_PROGRAM_LOOP_COUNT_NV ({}){}", name,
                                         b.count, kMaxLoopCount, where)),
               false, 0);
  }
  if (!(b.count > 0.0f)) {
    *pc = inst.jump + 1;
    return true;
  }
  blocks_.push_back(b);
  return true;
}

bool NvMachine::Push(const Reg& address, const std::string& where) {
  if (stack_.size() >= kMaxCallDepth) {
    return Terminate(
        fmt::format("PUSHA beyond MAX_PROGRAM_CALL_DEPTH_NV ({}) overflowed the call stack",
                    kMaxCallDepth),
        where);
  }
  stack_.push_back({-1, 0, address});
  return true;
}

bool NvMachine::Pop(Reg* address, const std::string& where) {
  if (stack_.empty()) return Terminate("POPA on an empty call stack", where);
  const Frame top = stack_.back();
  stack_.pop_back();
  if (top.return_pc >= 0) {
    return Terminate("POPA found a return address pushed by CAL on the call stack", where);
  }
  *address = top.address;
  return true;
}

bool NvMachine::LoopIndex(Val* index) const {
  for (auto it = blocks_.rbegin(); it != blocks_.rend(); ++it) {
    if (it->op != Opcode::LOOP) continue;
    *index = it->index;
    index->v = std::max(index->v, 0.0f);
    return true;
  }
  return false;
}

}  // namespace arbiter::arbvp::exec
