// Running ARB programs on Mesa: a GL context through OSMesa or EGL surfaceless, one point per
// input vector, RGBA32F readback of every output register (docs/design/architecture.md, Execution
// design). Fed from the same input model as the reference interpreter (arbvp/exec.h).
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "arbiter/arbvp/emit.h"
#include "arbiter/arbvp/exec.h"
#include "arbiter/arbvp/ir.h"

namespace arbiter::runtime {

enum class Backend : uint8_t { OSMesa, Egl };
// "osmesa" / "egl"; false when the name is neither.
bool ParseBackend(std::string_view name, Backend* backend);
std::string_view BackendName(Backend backend);

struct ExecOptions {
  Backend backend = Backend::OSMesa;
  std::string driver = "softpipe";  // validated (IsSupportedMesaDriver) before any context
};

// A vertex program, a fragment program, or a pair; each checked without errors.
struct ArbPrograms {
  const arbvp::Program* vertex = nullptr;
  const arbvp::Program* fragment = nullptr;
};

// One GL context that runs many programs (one at a time). Runs in the calling process: use
// the worker (worker.h) to isolate a driver crash or hang.
class ArbExecutor {
 public:
  virtual ~ArbExecutor() = default;
  // "softpipe, 4.5 (Compatibility Profile) Mesa 22.3.6" and the backend.
  virtual const std::string& description() const = 0;
  // Runs the program(s) on every vector of `inputs`: one VectorResult per vector, outputs
  // sorted with arbvp::ResultRegOrder, `undefined` left empty. On failure (Mesa rejected a
  // program, GL error, incomplete framebuffer) returns false and sets `error`.
  virtual bool Run(const ArbPrograms& programs, const arbvp::ExecInputs& inputs,
                   std::vector<arbvp::VectorResult>* results, std::string* error) = 0;
  // The mesa-glsl engine: runs the GLSL translation of the program(s) (TranslateChecked with
  // `emit`, mutations included) on the same context and inputs, with results in Run's shape
  // and register names so that the two compare 1:1. The translation's main becomes a
  // function whose output built-ins are read back through a generated main (a vertex shader
  // alone through varyings to a generated fragment shader, a fragment shader alone fed by a
  // generated vertex shader), with Run's colour clamping. GLSL has only x of
  // result.fogcoord and result.pointsize and z of result.depth: their written masks keep
  // only those. Fails (with `error`) where Run would, when the translation fails its
  // self-check, or when Mesa rejects the adapted shaders.
  virtual bool RunTranslated(const ArbPrograms& programs, const arbvp::EmitOptions& emit,
                             const arbvp::ExecInputs& inputs,
                             std::vector<arbvp::VectorResult>* results, std::string* error) = 0;
};

// Creates the context (validating the driver name first, disabling the shader cache). On
// failure returns null and sets `error` to a lower-case reason.
[[nodiscard]] std::unique_ptr<ArbExecutor> CreateArbExecutor(const ExecOptions& options,
                                                             std::string* error);

}  // namespace arbiter::runtime
