// Rewriting the programs of one run so that every result register they write reaches a
// float colour attachment (docs/design/architecture.md, Execution design): writes go to
// temporaries, copied at the end into varyings (vertex programs) or draw buffers (fragment
// programs), in as many passes as the attachments need.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "arbiter/arbvp/exec.h"
#include "arbiter/arbvp/ir.h"
#include "arbiter/runtime/exec.h"

namespace arbiter::runtime::exec {

// What runs: a vertex program with a generated pass-through fragment program, a fragment
// program with a generated pass-through vertex program, or a pair.
enum class RunMode : uint8_t { Vertex, Fragment, Pair };

// The generic attributes that carry a fragment program's inputs to the generated
// pass-through vertex program (fragment programs alone).
struct FragmentInputAttribs {
  int position = 0;
  int color = 1;
  int secondary_color = 2;
  int fogcoord = 3;
  int texcoord0 = 8;  // texcoord[k] in 8 + k
};
inline constexpr FragmentInputAttribs kFragmentInputAttribs{};

// A result register the run reports.
struct OutputSlot {
  arbvp::Binding binding;
  uint8_t written = 0;  // components the program's instructions write
};

// An attachment that holds no output: written (1,1,1,1) by every fragment that survives, so
// a KILled fragment reads (0,0,0,0) there.
inline constexpr int kAliveFlag = -1;

// One draw: both programs' text and what each colour attachment receives.
struct Pass {
  std::string vertex_text;
  std::string fragment_text;
  std::vector<int> attachments;  // index into RunPlan::outputs, or kAliveFlag
};

struct RunPlan {
  RunMode mode = RunMode::Vertex;
  std::vector<OutputSlot> outputs;  // in arbvp::ResultRegOrder
  std::vector<Pass> passes;
  // The generic attribute that carries the point's clip position (vertex programs); -1 when
  // the generated pass-through vertex program carries it (fragment programs alone), or when
  // the program reads all sixteen generic attributes: then program.env[position_env] of the
  // vertex target holds it, set before each point.
  int position_attrib = -1;
  int position_env = -1;
  bool reads_generic0 = false;  // the vertex program reads vertex.attrib[0], not position
  std::set<int> generics;       // the generic attributes the vertex program reads
};

// The context's limits the plan depends on.
struct ContextLimits {
  int max_draw_buffers = 8;  // GL_MAX_DRAW_BUFFERS (at most 8 are used)
  int max_vertex_env = 96;   // GL_MAX_PROGRAM_ENV_PARAMETERS_ARB of vertex programs
};

// Plans the passes. False (with `error`) when the programs cannot be rewritten.
[[nodiscard]] bool PlanRun(const ArbPrograms& programs, const ContextLimits& limits, RunPlan* plan,
                           std::string* error);

}  // namespace arbiter::runtime::exec
