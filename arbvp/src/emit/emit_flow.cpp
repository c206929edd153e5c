// The layout of main() and the NV flow instructions (emit_flow.h).
//
// A program without flow instructions is straight-line code. IF/ELSE/ENDIF, LOOP/ENDLOOP,
// REP/ENDREP and BRK become GLSL if, for and break when the program cannot run into
// MAX_PROGRAM_EXEC_INSTRUCTIONS_NV (a worst-case count, every loop at its 255 iterations,
// stays within it). GLSL has no goto, so BRA, CAL, RET, PUSHA and POPA, and loops that
// could reach the limit, run on a program-counter machine: a GLSL loop of at most
// MAX_PROGRAM_EXEC_INSTRUCTIONS_NV steps, each executing the one instruction arb_pc
// selects, with the call stack (return addresses and PUSHA's address registers) and the
// loop stack in arrays of the specifications' minimum depths. A run that reaches the
// instruction limit, overflows a stack or returns with an empty one ends there, as the
// specifications end it.
#include "emit/emit_flow.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "emit/emit_nv.h"
#include "emit/emit_shapes.h"

namespace arbiter::arbvp::emit {
namespace {

bool Opens(Opcode op) {
  return op == Opcode::IF || op == Opcode::ELSE || op == Opcode::LOOP || op == Opcode::REP;
}
bool Closes(Opcode op) {
  return op == Opcode::ELSE || op == Opcode::ENDIF || op == Opcode::ENDLOOP || op == Opcode::ENDREP;
}
// The instructions only the machine can run: jumps to labels and the shared call stack.
bool NeedsMachine(Opcode op) {
  return op == Opcode::BRA || op == Opcode::CAL || op == Opcode::RET || op == Opcode::PUSHA ||
         op == Opcode::POPA;
}
bool IsFlow(Opcode op) { return GetOpcodeInfo(op).klass == OpClass::Flow || NeedsMachine(op); }

// Component `comp` of a LOOP or REP operand when it is a constant, floored (LOOP and REP
// floor each component they read).
bool ConstantFloor(const Program& p, const Instruction& inst, int comp, float* value) {
  const SrcOperand& src = inst.src[0];
  const Variable& var = p.vars[static_cast<size_t>(src.var)];
  if (var.kind != VarKind::Param || src.relative) return false;
  const Binding& b = var.bindings.at(src.indexed ? static_cast<size_t>(src.index) : 0);
  if (b.kind != BindingKind::Constant) return false;
  const Swz s = src.swizzle[static_cast<size_t>(comp)];
  float v = s == Swz::Zero ? 0.0f : s == Swz::One ? 1.0f : b.value[static_cast<size_t>(s)];
  if (src.abs) v = std::fabs(v);
  if (src.negate) v = -v;
  *value = std::floor(v);
  return std::fabs(*value) < 1.0e9f;
}

// The most passes of a LOOP or REP block: its count when the operand is a constant, else
// MAX_PROGRAM_LOOP_COUNT_NV.
int64_t MaxPasses(const Program& p, const Instruction& inst) {
  float count = 0.0f;
  if (!ConstantFloor(p, inst, 0, &count)) return kMaxLoopCount;
  return static_cast<int64_t>(std::clamp(count, 0.0f, float{kMaxLoopCount}));
}

// The most instructions [begin, end) executes (flow instructions count): each branch of an
// IF at its longest, each loop body as often as its count allows. Stops counting past the
// limit.
int64_t StepBound(const Program& p, int begin, int end) {
  int64_t n = 0;
  for (int i = begin; i < end && n <= kMaxExecInstructions; ++i) {
    const Instruction& inst = p.instructions[static_cast<size_t>(i)];
    if (inst.op == Opcode::IF) {
      const int mid = inst.jump;
      const bool has_else = p.instructions[static_cast<size_t>(mid)].op == Opcode::ELSE;
      const int endif = has_else ? p.instructions[static_cast<size_t>(mid)].jump : mid;
      const int64_t taken = StepBound(p, i + 1, mid) + (has_else ? 1 : 0);
      const int64_t other = has_else ? StepBound(p, mid + 1, endif) : 0;
      n += 2 + std::max(taken, other);
      i = endif;
    } else if (inst.op == Opcode::LOOP || inst.op == Opcode::REP) {
      n += 1 + MaxPasses(p, inst) * (StepBound(p, i + 1, inst.jump) + 1);
      i = inst.jump;
    } else {
      n += 1;
    }
  }
  return n;
}

// "If a program has an instruction label "main", program execution begins with the
// instruction immediately following the instruction label."
int EntryPoint(const Program& p) {
  for (const Label& label : p.labels) {
    if (label.name == "main") return label.index;
  }
  return 0;
}

std::string IndentBy(const std::string& text, int depth) {
  std::string pad(static_cast<size_t>(2 * depth), ' ');
  std::string out;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    if (end > start) out += pad + text.substr(start, end - start);
    out += '\n';
    start = end + 1;
  }
  return out;
}

// The instruction's statements after its comment; a structured block's closing brace takes
// the comment on its line.
std::string Statement(Context& ctx, int index) {
  const Instruction& inst = ctx.program.instructions[static_cast<size_t>(index)];
  ctx.pc = index;
  std::string out = EmitInstruction(ctx, inst);
  if (!ctx.options.comments) return out;
  std::string comment = "// " + InstructionComment(ctx, inst);
  if (ctx.flow != FlowMode::Machine && Closes(inst.op)) {
    return out.substr(0, out.size() - 1) + "  " + comment + "\n";
  }
  return comment + "\n" + out;
}

int End(const Context& ctx) { return static_cast<int>(ctx.program.instructions.size()); }

// One machine step: the instruction at arb_pc == index, then the next arb_pc (the flow
// instructions set it themselves).
std::string Step(Context& ctx, int index) {
  std::string out = Statement(ctx, index);
  if (!IsFlow(ctx.program.instructions[static_cast<size_t>(index)].op)) {
    out += fmt::format("arb_pc = {};\n", index + 1);
  }
  return out;
}

// The steps of instructions [lo, hi), found by a binary search on arb_pc.
std::string Dispatch(Context& ctx, int lo, int hi) {
  if (hi - lo == 1) return Step(ctx, lo);
  const int mid = lo + (hi - lo) / 2;
  return fmt::format("if (arb_pc < {}) {{\n{}}} else {{\n{}}}\n", mid,
                     IndentBy(Dispatch(ctx, lo, mid), 1), IndentBy(Dispatch(ctx, mid, hi), 1));
}

bool Machine(const Context& ctx) { return ctx.flow == FlowMode::Machine; }

// `lines` when `condition` holds ("true": always).
std::string When(const std::string& condition, const std::string& lines) {
  if (condition == "true") return lines;
  return fmt::format("if ({}) {{\n{}}}\n", condition, IndentBy(lines, 1));
}

// Machine state, declared where first used.
void DeclareCallStack(Context& ctx) {
  DeclareLocal(ctx, "arb_sp", "int arb_sp = 0;  // call stack depth");
  DeclareLocal(
      ctx, "arb_stack",
      fmt::format("int arb_stack[{}];  // return addresses; -1: a PUSHA entry", kMaxCallDepth));
}
void DeclareLoopStack(Context& ctx) {
  DeclareLocal(ctx, "arb_ls", "int arb_ls = 0;  // open LOOP and REP blocks");
  DeclareLocal(
      ctx, "arb_loops",
      fmt::format("ivec3 arb_loops[{}];  // (count, increment, enclosing A0.x)", kMaxLoopDepth));
  DeclareLocal(ctx, "arb_a0", "int arb_a0 = 0;  // A0.x, the innermost LOOP's index");
  DeclareLocal(ctx, "arb_entry", "ivec3 arb_entry = ivec3(0);  // a loop stack entry");
}

// `array[index] = value;` through constant indices: softpipe loses a store at a dynamic
// index under divergent flow (Mesa 22.3; a read is right), which the machine's steps are.
std::string StoreAt(const std::string& array, const std::string& index, const std::string& value,
                    int size) {
  std::string out;
  for (int i = 0; i < size; ++i) {
    const std::string store = fmt::format("{}[{}] = {};\n", array, i, value);
    if (i + 1 == size) {
      out += "else " + store;
    } else {
      out += fmt::format("{}if ({} == {}) {}", i ? "else " : "", index, i, store);
    }
  }
  return out;
}

// The loop count of LOOP and REP: floor(x), "limited to MAX_PROGRAM_LOOP_COUNT_NV".
std::string LoopCount(Context& ctx, const Instruction& inst) {
  const bool plus_one = inst.op == Opcode::REP && ctx.Mutated(Mutation::RepCountPlusOne);
  if (float v = 0.0f; ConstantFloor(ctx.program, inst, 0, &v)) {
    return fmt::format("{}", MaxPasses(ctx.program, inst) + (plus_one ? 1 : 0));
  }
  return fmt::format("int(clamp(floor({}), 0.0, {}.0)){}", Source(ctx, Src(inst, 0), {0}).text,
                     kMaxLoopCount, plus_one ? " + 1" : "");
}

// LOOP's initial index (comp 1) or increment (comp 2): floor(y), floor(z).
std::string LoopFloor(Context& ctx, const Instruction& inst, int comp) {
  if (float v = 0.0f; ConstantFloor(ctx.program, inst, comp, &v)) {
    return fmt::format("{}", static_cast<int>(v));
  }
  return fmt::format("int(floor({}))", Source(ctx, Src(inst, 0), {comp}).text);
}

std::string EndProgram(const Context& ctx, std::string_view why) {
  return fmt::format("arb_pc = {};  // {}\n", End(ctx), why);
}

// LOOP and REP on the machine: a loop stack entry, or past the block when the count is not
// positive.
std::string MachineLoop(Context& ctx, const Instruction& inst, bool loop) {
  DeclareLoopStack(ctx);
  std::string enter = StoreAt("arb_loops", "arb_ls", "arb_entry", kMaxLoopDepth) + "arb_ls += 1;\n";
  if (loop) enter += fmt::format("arb_a0 = {};\n", LoopFloor(ctx, inst, 1));
  enter += fmt::format("arb_pc = {};\n", ctx.pc + 1);
  std::string push = fmt::format(
      "arb_entry = ivec3({}, {}, arb_a0);\nif (arb_entry.x > 0) {{\n{}}} else "
      "{{\n  arb_pc = {};\n}}\n",
      LoopCount(ctx, inst), loop ? LoopFloor(ctx, inst, 2) : "0", IndentBy(enter, 1),
      inst.jump + 1);
  return fmt::format("if (arb_ls == {}) {{\n{}}} else {{\n{}}}\n", kMaxLoopDepth,
                     IndentBy(EndProgram(ctx, "MAX_PROGRAM_LOOP_DEPTH_NV blocks open: the end"), 1),
                     IndentBy(push, 1));
}

// ENDLOOP and ENDREP on the machine: "LoopCount--; LoopIndex += LoopIncr; if (LoopCount >
// 0) continue at the top", else the block's entry is popped (and the enclosing A0.x back).
std::string MachineEndLoop(Context& ctx, const Instruction& inst, bool loop) {
  DeclareLoopStack(ctx);
  std::string out = "arb_entry = arb_loops[arb_ls - 1];\narb_entry.x -= 1;\n";
  if (loop) out += "arb_a0 += arb_entry.y;\n";
  std::string again = StoreAt("arb_loops", "arb_ls - 1", "arb_entry", kMaxLoopDepth) +
                      fmt::format("arb_pc = {};\n", inst.jump + 1);
  std::string pop = "arb_ls -= 1;\n";
  if (loop) pop += "arb_a0 = arb_entry.z;\n";
  pop += fmt::format("arb_pc = {};\n", ctx.pc + 1);
  return out + fmt::format("if (arb_entry.x > 0) {{\n{}}} else {{\n{}}}\n", IndentBy(again, 1),
                           IndentBy(pop, 1));
}

// Structured LOOP and REP: a counter (and LOOP's index and increment) per block.
std::string StructuredLoop(Context& ctx, const Instruction& inst, bool loop) {
  const int n = ++ctx.loops;
  const std::string count = fmt::format("arb_loop{}", n);
  DeclareLocal(ctx, count, fmt::format("int {} = 0;  // loop count", count));
  std::string out = fmt::format("{} = {};\n", count, LoopCount(ctx, inst));
  if (loop) {
    const std::string index = fmt::format("arb_a0_{}", n);
    const std::string incr = fmt::format("arb_incr{}", n);
    DeclareLocal(ctx, index, fmt::format("int {} = 0;  // A0.x of a LOOP block", index));
    DeclareLocal(ctx, incr, fmt::format("int {} = 0;  // its increment", incr));
    out += fmt::format("{} = {};\n{} = {};\n", index, LoopFloor(ctx, inst, 1), incr,
                       LoopFloor(ctx, inst, 2));
    ctx.open_loops.push_back(n);
  }
  return out + fmt::format("for (; {0} > 0; --{0}) {{\n", count);
}

}  // namespace

std::string EmitBody(Context& ctx) {
  const Program& p = ctx.program;
  const int entry = EntryPoint(p);
  bool flow = false;
  bool machine = false;
  for (const Instruction& inst : p.instructions) {
    flow = flow || IsFlow(inst.op);
    machine = machine || NeedsMachine(inst.op);
  }
  machine = machine || (flow && StepBound(p, entry, End(ctx)) > kMaxExecInstructions);
  ctx.flow = machine ? FlowMode::Machine : flow ? FlowMode::Structured : FlowMode::Straight;
  if (machine) {
    DeclareLocal(ctx, "arb_pc", fmt::format("int arb_pc = {};  // the next instruction", entry));
    return fmt::format(
        "for (int arb_step = 0; arb_step < {}; ++arb_step) {{  // "
        "MAX_PROGRAM_EXEC_INSTRUCTIONS_NV\n"
        "  if (arb_pc >= {}) break;\n{}}}\n",
        kMaxExecInstructions, End(ctx), IndentBy(Dispatch(ctx, 0, End(ctx)), 1));
  }
  std::string body;
  int depth = 0;
  for (int i = entry; i < End(ctx); ++i) {
    const Opcode op = p.instructions[static_cast<size_t>(i)].op;
    if (Closes(op)) --depth;
    body += IndentBy(Statement(ctx, i), depth);
    if (Opens(op)) ++depth;
  }
  return body;
}

// BRA: to the label's instruction when the test holds.
std::string BRA(Context& ctx, const Instruction& inst) {
  std::string test = CcAnyTest(ctx, inst.cond);
  if (test == "true") return fmt::format("arb_pc = {};\n", inst.jump);
  return fmt::format("arb_pc = {} ? {} : {};\n", test, inst.jump, ctx.pc + 1);
}

// BRK: to the instruction after the loop's ENDLOOP or ENDREP.
std::string BRK(Context& ctx, const Instruction& inst) {
  if (ctx.Mutated(Mutation::BrkIgnored)) {
    return Machine(ctx) ? fmt::format("arb_pc = {};\n", ctx.pc + 1) : "// (BRK ignored)\n";
  }
  std::string test = CcAnyTest(ctx, inst.cond);
  if (!Machine(ctx)) return test == "true" ? "break;\n" : fmt::format("if ({}) break;\n", test);
  const bool loop = ctx.program.instructions[static_cast<size_t>(inst.jump)].op == Opcode::ENDLOOP;
  DeclareLoopStack(ctx);
  std::string leave = "arb_ls -= 1;\n";
  if (loop) leave += "arb_a0 = arb_loops[arb_ls].z;\n";
  leave += fmt::format("arb_pc = {};\n", inst.jump + 1);
  if (test == "true") return leave;
  return fmt::format("arb_pc = {};\n", ctx.pc + 1) + When(test, leave);
}

bool Has(const Program& p, Opcode op) {
  for (const Instruction& inst : p.instructions) {
    if (inst.op == op) return true;
  }
  return false;
}
bool HasLoops(const Program& p) { return Has(p, Opcode::LOOP) || Has(p, Opcode::REP); }

// CAL: the return address pushed, then to the label; past MAX_PROGRAM_CALL_DEPTH_NV
// entries the program ends. The open loop blocks are noted: RET leaves the callee's.
std::string CAL(Context& ctx, const Instruction& inst) {
  DeclareCallStack(ctx);
  std::string push = StoreAt("arb_stack", "arb_sp", std::to_string(ctx.pc + 1), kMaxCallDepth);
  if (HasLoops(ctx.program)) {
    DeclareLocal(
        ctx, "arb_stack_ls",
        fmt::format("int arb_stack_ls[{}];  // the open loop blocks at each CAL", kMaxCallDepth));
    push += StoreAt("arb_stack_ls", "arb_sp", "arb_ls", kMaxCallDepth);
  }
  push += fmt::format("arb_sp += 1;\narb_pc = {};\n", inst.jump);
  std::string call =
      fmt::format("if (arb_sp == {}) {{\n{}}} else {{\n{}}}\n", kMaxCallDepth,
                  IndentBy(EndProgram(ctx, "call stack overflow: the end"), 1), IndentBy(push, 1));
  return fmt::format("arb_pc = {};\n", ctx.pc + 1) + When(CcAnyTest(ctx, inst.cond), call);
}

std::string ELSE(Context& ctx, const Instruction& inst) {
  if (!Machine(ctx)) return "} else {\n";
  return fmt::format("arb_pc = {};  // the end of the IF part: to ENDIF\n", inst.jump);
}

std::string ENDIF(Context& ctx, const Instruction&) {
  if (!Machine(ctx)) return "}\n";
  return fmt::format("arb_pc = {};\n", ctx.pc + 1);
}

// Structured ENDLOOP: the index advanced at the end of each pass (the line belongs to the
// body, one level in).
std::string ENDLOOP(Context& ctx, const Instruction& inst) {
  if (Machine(ctx)) return MachineEndLoop(ctx, inst, true);
  const int n = ctx.open_loops.back();
  ctx.open_loops.pop_back();
  return fmt::format("  arb_a0_{0} += arb_incr{0};\n}}\n", n);
}

std::string ENDREP(Context& ctx, const Instruction& inst) {
  if (Machine(ctx)) return MachineEndLoop(ctx, inst, false);
  return "}\n";
}

// IF: on when the test holds, else after its ELSE (or ENDIF).
std::string IF(Context& ctx, const Instruction& inst) {
  std::string test = CcAnyTest(ctx, inst.cond);
  if (!Machine(ctx)) return fmt::format("if ({}) {{\n", test);
  if (test == "true") return fmt::format("arb_pc = {};\n", ctx.pc + 1);
  return fmt::format("arb_pc = {} ? {} : {};\n", test, ctx.pc + 1, inst.jump + 1);
}

// LOOP: (x, y, z) = (count, initial A0.x, increment), each floored.
std::string LOOP(Context& ctx, const Instruction& inst) {
  return Machine(ctx) ? MachineLoop(ctx, inst, true) : StructuredLoop(ctx, inst, true);
}

// POPA: the address register from the top of the call stack, which must hold one.
std::string POPA(Context& ctx, const Instruction& inst) {
  DeclareCallStack(ctx);
  std::string pop = "arb_sp -= 1;\n" +
                    AssignAddress(ctx, inst,
                                  [](const Comps& comps) {
                                    std::string v = "arb_saved[arb_sp]";
                                    return comps == AllComps() ? v : v + "." + Letters(comps);
                                  }) +
                    fmt::format("arb_pc = {};\n", ctx.pc + 1);
  return fmt::format("if (arb_sp == 0 || arb_stack[arb_sp - 1] >= 0) {{\n{}}} else {{\n{}}}\n",
                     IndentBy(EndProgram(ctx, "no address register on the stack: the end"), 1),
                     IndentBy(pop, 1));
}

// PUSHA: the address register onto the call stack.
std::string PUSHA(Context& ctx, const Instruction& inst) {
  DeclareCallStack(ctx);
  DeclareLocal(
      ctx, "arb_saved",
      fmt::format("ivec4 arb_saved[{}];  // address registers PUSHA saved", kMaxCallDepth));
  std::string push = StoreAt("arb_stack", "arb_sp", "-1", kMaxCallDepth) +
                     StoreAt("arb_saved", "arb_sp",
                             ctx.var_names[static_cast<size_t>(Src(inst, 0).var)], kMaxCallDepth) +
                     fmt::format("arb_sp += 1;\narb_pc = {};\n", ctx.pc + 1);
  return fmt::format("if (arb_sp == {}) {{\n{}}} else {{\n{}}}\n", kMaxCallDepth,
                     IndentBy(EndProgram(ctx, "call stack overflow: the end"), 1),
                     IndentBy(push, 1));
}

std::string REP(Context& ctx, const Instruction& inst) {
  return Machine(ctx) ? MachineLoop(ctx, inst, false) : StructuredLoop(ctx, inst, false);
}

// RET: to the address on top of the call stack, leaving the loop blocks the callee left
// open; with an empty stack the program ends (normally), on an address register PUSHA left
// there it ends too (abnormally).
std::string RET(Context& ctx, const Instruction& inst) {
  DeclareCallStack(ctx);
  std::string back = "arb_pc = arb_stack[arb_sp];\n";
  if (Has(ctx.program, Opcode::PUSHA)) {
    back +=
        fmt::format("if (arb_pc < 0) arb_pc = {};  // an address register: the end\n", End(ctx));
  }
  if (HasLoops(ctx.program)) {
    DeclareLoopStack(ctx);
    back +=
        "if (arb_ls > arb_stack_ls[arb_sp]) {\n  arb_a0 = arb_loops[arb_stack_ls[arb_sp]].z;\n"
        "  arb_ls = arb_stack_ls[arb_sp];\n}\n";
  }
  std::string ret =
      fmt::format("if (arb_sp == 0) {{\n{}}} else {{\n  arb_sp -= 1;\n{}}}\n",
                  IndentBy(EndProgram(ctx, "empty call stack: the end"), 1), IndentBy(back, 1));
  return fmt::format("arb_pc = {};\n", ctx.pc + 1) + When(CcAnyTest(ctx, inst.cond), ret);
}

}  // namespace arbiter::arbvp::emit
