// The generated mains of the Vulkan engine: they feed the lowered shaders' globals from a
// storage buffer of inputs (one record per vector), call arb_main, and store every output the
// GL run reports into a storage buffer of outputs (exact: no attachment, no clamping).
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "arbiter/runtime/glsl_exec.h"
#include "glsl_exec/run.h"

namespace arbiter::runtime::glsl_vulkan {

inline constexpr int kInputBinding = 30;
inline constexpr int kOutputBinding = 31;

// Where each number lives: the input record of a vector is `input_stride` vec4s (vec4 0 is
// the point's clip position, then each slot's columns), the outputs `vertex_stride` floats
// per vector, then (from vertex_stride * count) `fragment_stride` per vector: 1.0 when the
// fragment survived, then each fragment output.
struct IoPlan {
  struct Input {
    std::string name;  // the slot's: "gl_Vertex", "gl_TexCoord[1]", "light[2]"
    std::string type;
    int first = 0;  // vec4 of the record
  };
  int input_stride = 1;
  std::vector<Input> inputs;
  std::vector<glsl_exec::VertexOutput> vertex_outputs;
  int vertex_stride = 0;
  glsl_exec::FragmentOutputs fragment_outputs;
  int fragment_stride = 0;
};

// `access` ("gl_TexCoord[1]", "l.sample", "w[2]") with each name as the lowering spells it
// ("arb_gl_TexCoord[1]", "l.arb_u_sample"), and back.
std::string LowerAccess(std::string_view access);
std::string UserAccess(std::string_view lowered);

IoPlan PlanIo(const GlslShaders& shaders, const GlslExecInputs& inputs);

// The lowered texts completed with their mains (`vertex` empty for a fragment shader alone:
// a generated one feeds it; `fragment` empty for a vertex shader alone). `height` is the
// framebuffer's, for GL's gl_FragCoord.y.
struct Generated {
  std::string vertex;
  std::string fragment;
};
Generated GenerateMains(const GlslShaders& shaders, const std::string& lowered_vertex,
                        const std::string& lowered_fragment, const IoPlan& plan, size_t count,
                        int height);

}  // namespace arbiter::runtime::glsl_vulkan
