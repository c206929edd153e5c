// The inputs `arbiter verify` runs programs on: edge and random vectors, with a random
// well-conditioned GL state, program parameters and textures per batch; and a description of
// the inputs a program reads (for the disagreement report).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "arbiter/arbvp/exec.h"
#include "arbiter/arbvp/ir.h"

namespace arbiter::arbvp {

struct GenerateOptions {
  int random_vectors = 64;  // besides the edge vectors
  uint64_t seed = 1;
};

// One set of inputs drawn with one GL state / parameter / texture draw. Vectors within a
// batch share state.
struct InputBatch {
  std::string name;  // "edge", "random 1", "random 2", ...
  ExecInputs inputs;
};

// Batch 0 holds the edge vectors (one per value of EdgeValues(): every attribute component a
// program reads cycles through them with its own stride); then ceil(random_vectors / 64)
// random batches of at most 64 vectors each, each with its own random state, parameters and
// textures. Deterministic: the same program(s), options and seed give bit-identical batches on
// every machine (std::mt19937_64 bits, conversions written here, no libm transcendentals).
// `vertex` and/or `fragment` may be null (not both); a pair takes its fragment inputs from
// the vertex program, so only vertex inputs are generated then.
std::vector<InputBatch> GenerateInputs(const Program* vertex, const Program* fragment,
                                       const GenerateOptions& options);

// The special values the edge batch cycles through, in order: signed zeros, small integers
// and halves, tiny and huge magnitudes, pi, denormals, the float range's ends, infinities
// and NaN.
const std::vector<float>& EdgeValues();

// One line per input the program(s) read for vector `index` of `inputs`: the attribute,
// parameter and state bindings read (bindings that instructions use; every element of a
// relative-addressed array) with their values, and the textures sampled, e.g.
// "vertex.attrib[1] = (1, -0, inf, nan)", "program.local[3] = (...)",
// "state.matrix.mvp.row[0] = (...)", "texture[0] = 2D 4x4 linear repeat". Sorted and
// unique. For a pair: the vertex program's attributes, and both programs' parameters (then
// prefixed "vertex." / "fragment."), state and textures.
std::vector<std::string> DescribeReadInputs(const Program* vertex, const Program* fragment,
                                            const ExecInputs& inputs, size_t index);

}  // namespace arbiter::arbvp
