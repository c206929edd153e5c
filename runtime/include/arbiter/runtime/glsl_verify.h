// Differential verification of GLSL 1.10/1.20 shaders (docs/verify.md, "GLSL shaders"): a
// shader, or a vertex + fragment pair, runs on every engine over generated edge and random
// inputs (attributes or varyings, uniforms, textures, GL state), and each output component
// is compared with the first engine's under the GLSL tolerance model. Disagreements that an
// instrumented run shows to come from undefined behaviour, or that a run on slightly
// perturbed inputs shows to lie at a discontinuity, are named and not counted.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "arbiter/arbvp/generate.h"
#include "arbiter/compiler/source.h"
#include "arbiter/glsl/reflect.h"
#include "arbiter/runtime/exec.h"
#include "arbiter/runtime/glsl_exec.h"
#include "arbiter/runtime/verify.h"
#include "arbiter/runtime/worker.h"

namespace arbiter::runtime {

// The GLSL engines: Mesa's GLSL compiler on each of its GL drivers, and glslang to SPIR-V on
// lavapipe (glsl_vulkan.h).
inline constexpr const char* kGlslEngineSoftpipe = "softpipe";
inline constexpr const char* kGlslEngineLlvmpipe = "llvmpipe";
inline constexpr const char* kGlslEngineVulkan = "vulkan";
const std::vector<std::string>& GlslEngineNames();
// The Verdict::not_applicable key under which verify says why it has no undefined-behaviour
// probe for a subject (its disagreements are then all reported).
inline constexpr const char* kGlslProbeName = "undefined-behaviour probe";

struct GlslVerifySubject {
  std::string name;  // the file(s), for the report
  // The shaders' sources (one file each), checked without errors, and their reflections.
  const compiler::SourceFile* vertex = nullptr;
  const compiler::SourceFile* fragment = nullptr;
  const glsl::Reflection* vertex_reflection = nullptr;
  const glsl::Reflection* fragment_reflection = nullptr;
};

struct GlslVerifyOptions {
  std::vector<std::string> engines{kGlslEngineSoftpipe, kGlslEngineLlvmpipe, kGlslEngineVulkan};
  Backend backend = Backend::OSMesa;  // of the Mesa GL engines
  int jobs = 1;                       // subjects verified at a time
  WorkerLimits limits;                // of each engine's run of a subject
  arbvp::GenerateOptions generate;
  // Test-only: changes an engine's results before they are compared (the injection test).
  std::function<void(const std::string& engine, size_t batch, std::vector<GlslVectorResult>*)>
      tamper;
};

// The inputs of one batch, as `exec` takes them: one GL state, uniform values and textures,
// and its vectors.
struct GlslBatch {
  std::string name;  // "edge", "random 1", ...
  GlslExecInputs inputs;
  std::vector<bool> float_uniforms;  // per inputs.uniforms entry: it holds floats
};

// The batches a subject is verified on: the edge batch (every float input cycles through the
// finite edge values) and ceil(random_vectors / 64) random batches, each with its own
// uniforms, GL state and textures. Deterministic for a seed. Empty (with `error`) when an
// input's type cannot be generated.
std::vector<GlslBatch> GenerateGlslInputs(const GlslVerifySubject& subject,
                                          const arbvp::GenerateOptions& options,
                                          std::string* error);

// The tolerance of one output component under the GLSL model: `a` and `b` are two engines'
// values, `scale` the largest magnitude among the vector's inputs, `loose` whether the shader
// calls a built-in the specification gives no precision (docs/verify.md), `textured` whether
// it samples a texture.
struct GlslTolerance {
  bool loose = false;
  bool textured = false;
};
GlslTolerance ToleranceOf(const GlslVerifySubject& subject);
bool WithinTolerance(float a, float b, float scale, const GlslTolerance& tolerance);

// Verifies every subject; verdicts in subject order. The first engine is the baseline every
// other one is compared with.
std::vector<Verdict> VerifyGlsl(const std::vector<GlslVerifySubject>& subjects,
                                const GlslVerifyOptions& options);

}  // namespace arbiter::runtime
