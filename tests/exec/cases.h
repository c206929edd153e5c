// The engine-neutral table of execution cases: programs, inputs and the values the SPECS
// give (never a driver's), for the reference interpreter and later for Mesa.
#pragma once

#include <cstdint>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "arbiter/arbvp/exec.h"

namespace arbiter::exec_cases {

using arbvp::Vec4;

// How a computed component is compared with the expected one.
//   Exact     same float (NaN matches NaN; +0 and -0 differ): IEEE float32 is exact there
//   Relative  |got - want| <= bound * |want| (inf and NaN must match exactly): the
//             approximated operations (EX2 LG2 POW RCP RSQ SIN COS, EXP.z LOG.z LIT.z,
//             fog), which the specs define only to an accuracy
//   Absolute  |got - want| <= bound: approximations near 0 (SIN, COS, fog blends)
enum class Tolerance : uint8_t { Exact, Relative, Absolute };

// The accuracy ARBvp issue 28 gives EXP and LOG (2^-11), which docs/design/architecture.md applies
// to every approximated operation.
inline constexpr float kApprox = 1.0f / 2048.0f;

struct Expect {
  size_t vector = 0;
  std::string reg;     // the output's name, e.g. "result.color", "result.texcoord[1]"
  uint8_t mask = 0xF;  // the components this expectation checks
  Vec4 value{0.0f, 0.0f, 0.0f, 0.0f};
  Tolerance tolerance = Tolerance::Exact;
  float bound = 0.0f;
  // Components the specs leave undefined: the interpreter must tag each (reason containing
  // `reason`); other engines skip them. Their `value` is not compared.
  uint8_t undefined = 0;
  std::string reason;
  int written = -1;     // >= 0: the exact written mask the engine must report
  bool absent = false;  // the register must not be reported at all
};

struct ExecCase {
  std::string name;
  std::string spec;           // the clause the expectation comes from
  std::string vertex_text;    // "" when the case runs a fragment program alone
  std::string fragment_text;  // "" when the case runs a vertex program alone
  // Fills the inputs; the table starts them with one default vector.
  std::function<void(arbvp::ExecInputs&)> setup;
  std::vector<Expect> expects;
  std::vector<size_t> killed;  // vectors a KIL must discard (the others must survive)
};

// Every case.
const std::vector<ExecCase>& AllExecCases();

// gtest prints a case by its name.
inline void PrintTo(const ExecCase& c, std::ostream* os) { *os << c.name; }

}  // namespace arbiter::exec_cases
