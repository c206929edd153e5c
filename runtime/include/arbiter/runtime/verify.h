// Differential verification (docs/design/architecture.md, Verification policy): a program runs on
// the reference interpreter (ref), on Mesa as ARB assembly (mesa-arb) and on Mesa as its GLSL
// translation (mesa-glsl), over generated edge and random inputs; every written output
// component is compared with the interpreter's under the tolerance model (docs/verify.md).
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "arbiter/arbvp/emit.h"
#include "arbiter/arbvp/exec.h"
#include "arbiter/arbvp/generate.h"
#include "arbiter/arbvp/ir.h"
#include "arbiter/compiler/source.h"
#include "arbiter/runtime/exec.h"
#include "arbiter/runtime/worker.h"

namespace arbiter::runtime {

inline constexpr const char* kEngineRef = "ref";
inline constexpr const char* kEngineMesaArb = "mesa-arb";
inline constexpr const char* kEngineMesaGlsl = "mesa-glsl";
// The target engines (docs/verify.md): each target's translation, state as uniforms fed
// through the binding map and the host library (glstate), on an EGL context of its API (on
// a Vulkan device for vulkan-spirv).
inline constexpr const char* kEngineMesaGlsl330 = "mesa-glsl330";  // desktop 3.3 core profile
inline constexpr const char* kEngineMesaEs300 = "mesa-es300";      // OpenGL ES 3.0
inline constexpr const char* kEngineMesaEs100 = "mesa-es100";      // OpenGL ES 2.0
// The vk450 translation compiled to SPIR-V and run on Mesa's lavapipe (Vulkan).
inline constexpr const char* kEngineVulkanSpirv = "vulkan-spirv";
// The target engines and the translation target each runs.
struct TargetEngineInfo {
  const char* name;
  arbvp::EmitTarget target;
};
inline constexpr TargetEngineInfo kTargetEngines[] = {
    {kEngineMesaGlsl330, arbvp::EmitTarget::Glsl330},
    {kEngineMesaEs300, arbvp::EmitTarget::Es300},
    {kEngineMesaEs100, arbvp::EmitTarget::Es100},
    {kEngineVulkanSpirv, arbvp::EmitTarget::Vk450},
};

struct VerifyOptions {
  ExecOptions exec;
  // Worker processes at a time, each verifying a chunk of programs on one GL context.
  int jobs = 1;
  // Of each worker; timeout_ms is per program.
  WorkerLimits limits;
  arbvp::GenerateOptions generate;
  bool mesa_arb = true;
  bool mesa_glsl = true;
  arbvp::EmitOptions emit;  // the translation mesa-glsl runs (a test-only mutation included)
  // The target engines to run (kTargetEngines' names), with emit's mutation; always on EGL
  // (OSMesa makes no core or ES context), whatever exec.backend says; vulkan-spirv on
  // lavapipe, whatever exec.driver says.
  std::vector<std::string> targets;
};

// One program, or a vertex + fragment pair, checked without errors.
struct VerifySubject {
  std::string name;  // the file(s), for the report
  const arbvp::Program* vertex = nullptr;
  const arbvp::Program* fragment = nullptr;
  const compiler::SourceFile* vertex_source = nullptr;
  const compiler::SourceFile* fragment_source = nullptr;
};

// One output component (or a kill) on which a Mesa engine and the interpreter disagree.
struct Disagreement {
  std::string batch;  // "edge", "random 1", ...
  size_t vector = 0;
  std::string reg;     // "result.color"; empty for a kill
  int component = -1;  // 0..3; -1 for a kill or a missing register
  // GLSL: the component as GLSL names it ("gl_Position.y", "m[1].z", "f"); empty for ARB,
  // whose components are register.xyzw.
  std::string label;
  std::string what;  // "killed by ref only", "not written by mesa-glsl"; empty for a value
  float tolerance = 0.0f;
  // The value of each engine that ran ("ref", "mesa-arb", "mesa-glsl"), and those that
  // disagree with ref.
  std::map<std::string, float> values;
  std::vector<std::string> engines;
  std::vector<std::string> inputs;  // DescribeReadInputs of the vector
};

struct Verdict {
  std::string name;
  std::string error;  // an engine could not run the program (then nothing was compared)
  size_t vectors = 0;
  size_t compared = 0;                       // components compared, per Mesa engine
  std::map<std::string, size_t> undefined;   // reason -> components not compared
  size_t unstable = 0;                       // within rounding of a discontinuity
  std::map<std::string, size_t> deviations;  // known Mesa deviation -> components
  std::vector<Disagreement> disagreements;
  // Engine -> why it did not run the program: its target refuses a construct (the
  // diagnostic names it and the target). Not an error.
  std::map<std::string, std::string> not_applicable;
};

// Verifies every subject, in worker processes (options.jobs at a time); verdicts in subject
// order. A subject that crashes or hangs its worker is retried alone, so that the others
// still get a verdict and it gets the error.
std::vector<Verdict> Verify(const std::vector<VerifySubject>& subjects,
                            const VerifyOptions& options);

// Compares one Mesa engine's results with the interpreter's (`ref`, with its tolerances
// and tags) on one batch, adding to `verdict`. `applicable` are the deviations
// (arbvp::ApplicableDeviations) of the engine and driver. Disagreements get the engine's
// name in `engines` and its value in `values`.
void CompareWithReference(const std::vector<arbvp::VectorResult>& ref,
                          const std::vector<arbvp::VectorResult>& engine, const std::string& name,
                          uint32_t applicable, const std::string& batch, Verdict* verdict);

}  // namespace arbiter::runtime
