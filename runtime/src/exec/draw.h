// Drawing one GL_POINTS point per input vector at its pixel, with its attributes.
#pragma once

#include <cstdint>
#include <vector>

#include "arbiter/arbvp/exec.h"
#include "exec/exec_gl.h"
#include "exec/program_rewrite.h"

namespace arbiter::runtime::exec {

// The clip coordinates that put a point at the centre of FragmentPixel(index) with window
// depth `depth` (under the state's depth range), w = 1.
arbvp::Vec4 PixelClipPosition(size_t index, int width, int height, float depth,
                              const arbvp::GlState& state);

// Sends every vector of `inputs` as one point: the fragment inputs in the generic attributes
// the pass-through vertex program reads (fragment programs alone), or the vertex inputs plus
// the pixel position in plan.position_attrib or plan.position_env (vertex programs), or in
// the uniform `pixel_uniform` of the current GLSL program when it is not -1.
void DrawPoints(const ExecGl& gl, const RunPlan& plan, const arbvp::ExecInputs& inputs, int width,
                int height, GLint pixel_uniform = -1);

// The pixels read back become one VectorResult per vector: a fragment whose alive flag is
// not 1 was killed (`alive` empty: no flag); `values[s]` holds plan.outputs[s]'s pixels.
// `written_mask` (optional) narrows each output's written mask to what the engine carries.
void CollectResults(const RunPlan& plan, const std::vector<std::vector<float>>& values,
                    const std::vector<float>& alive, uint8_t (*written_mask)(const arbvp::Binding&),
                    std::vector<arbvp::VectorResult>* results);

}  // namespace arbiter::runtime::exec
