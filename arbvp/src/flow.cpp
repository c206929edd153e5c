// Flow structure of the NV options (flow.h).
#include "flow.h"

#include <fmt/format.h>

#include <map>
#include <vector>

namespace arbiter::arbvp {

void ResolveFlow(Program* program, const compiler::SourceFile& source, const FlowReport& report) {
  std::map<std::string, const Label*, std::less<>> labels;
  for (const Label& label : program->labels) {
    auto [it, fresh] = labels.emplace(label.name, &label);
    if (!fresh) {
      compiler::Diagnostic* d = report(Diag::FlowLabelRepeated, label.range,
                                       fmt::format("label '{}' is defined twice", label.name));
      if (d) d->notes.push_back({&source, it->second->range, "first defined here"});
    }
  }
  // Open IF and loop blocks, innermost last.
  std::vector<int> blocks;
  // The open block instruction `i` closes (an ENDIF closes an IF or its ELSE), or -1.
  auto close = [&](int i, Opcode opener, std::string_view what) -> int {
    Instruction& inst = program->instructions[static_cast<size_t>(i)];
    if (blocks.empty()) {
      report(Diag::FlowUnmatched, inst.opcode_range,
             fmt::format("{} without {}", GetOpcodeInfo(inst.op).name, what));
      return -1;
    }
    const int open = blocks.back();
    Instruction& first = program->instructions[static_cast<size_t>(open)];
    const bool matches =
        first.op == opener || (first.op == Opcode::ELSE && inst.op == Opcode::ENDIF);
    if (!matches) {
      compiler::Diagnostic* d =
          report(Diag::FlowUnmatched, inst.opcode_range,
                 fmt::format("{} cannot close the open {} block", GetOpcodeInfo(inst.op).name,
                             GetOpcodeInfo(first.op).name));
      if (d) d->notes.push_back({&source, first.opcode_range, "the block opens here"});
      return -1;
    }
    return open;
  };
  for (size_t i = 0; i < program->instructions.size(); ++i) {
    Instruction& inst = program->instructions[i];
    const int index = static_cast<int>(i);
    switch (inst.op) {
      case Opcode::BRA:
      case Opcode::CAL: {
        auto it = labels.find(inst.label);
        if (it == labels.end()) {
          report(Diag::FlowLabelUndefined, inst.label_range,
                 fmt::format("{} to label '{}', which the program does not define",
                             GetOpcodeInfo(inst.op).name, inst.label));
        } else {
          inst.jump = it->second->index;
        }
        break;
      }
      case Opcode::IF:
      case Opcode::LOOP:
      case Opcode::REP:
        blocks.push_back(index);
        break;
      case Opcode::ELSE: {
        const int open = close(index, Opcode::IF, "IF");
        if (open >= 0) {
          program->instructions[static_cast<size_t>(open)].jump = index;
          blocks.back() = index;  // ENDIF now closes the ELSE
        }
        break;
      }
      case Opcode::ENDIF:
      case Opcode::ENDLOOP:
      case Opcode::ENDREP: {
        const Opcode opener = inst.op == Opcode::ENDIF     ? Opcode::IF
                              : inst.op == Opcode::ENDLOOP ? Opcode::LOOP
                                                           : Opcode::REP;
        const int open = close(index, opener,
                               inst.op == Opcode::ENDIF     ? "IF"
                               : inst.op == Opcode::ENDLOOP ? "LOOP"
                                                            : "REP");
        if (open < 0) break;
        program->instructions[static_cast<size_t>(open)].jump = index;
        if (inst.op != Opcode::ENDIF) inst.jump = open;
        blocks.pop_back();
        break;
      }
      case Opcode::BRK: {
        int loop = -1;
        for (auto it = blocks.rbegin(); it != blocks.rend(); ++it) {
          Opcode op = program->instructions[static_cast<size_t>(*it)].op;
          if (op == Opcode::LOOP || op == Opcode::REP) {
            loop = *it;
            break;
          }
        }
        if (loop < 0) {
          report(Diag::FlowBreakOutsideLoop, inst.opcode_range, "BRK outside a LOOP or REP block");
        } else {
          inst.jump = loop;  // the loop's LOOP/REP; its end is that instruction's jump
        }
        break;
      }
      default:
        break;
    }
    // NV_fragment_program2 3.11.3.Y: "A fragment program that accesses A0.x outside a
    // LOOP/ENDLOOP block will fail to load."
    if (program->kind == ProgramKind::Fragment) {
      for (size_t s = 0; s < inst.src_count; ++s) {
        if (!inst.src[s].relative) continue;
        bool in_loop = false;
        for (int open : blocks) {
          in_loop = in_loop || program->instructions[static_cast<size_t>(open)].op == Opcode::LOOP;
        }
        if (!in_loop) {
          report(Diag::FlowLoopIndexOutsideLoop, inst.src[s].range,
                 "the loop index A0.x exists only inside a LOOP/ENDLOOP block");
        }
      }
    }
  }
  // BRK leaves for the end of its loop.
  for (Instruction& inst : program->instructions) {
    if (inst.op == Opcode::BRK && inst.jump >= 0) {
      inst.jump = program->instructions[static_cast<size_t>(inst.jump)].jump;
    }
  }
  for (int open : blocks) {
    const Instruction& inst = program->instructions[static_cast<size_t>(open)];
    report(Diag::FlowUnmatched, inst.opcode_range,
           fmt::format("the {} block is not closed before END",
                       inst.op == Opcode::ELSE ? "ELSE" : GetOpcodeInfo(inst.op).name));
  }
}

}  // namespace arbiter::arbvp
