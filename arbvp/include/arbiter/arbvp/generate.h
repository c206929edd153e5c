// The inputs `arbiter verify` runs programs on: edge and random vectors, with a random
// well-conditioned GL state, program parameters and textures per batch; and a description of
// the inputs a program reads (for the disagreement report).
#pragma once

#include <cstdint>
#include <memory>
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

// The generator's random draws for another language's inputs (the GLSL verify): the same
// numbers on every machine for a seed, a batch and a stream.
namespace gen {
class Rng;
}
class InputDraw {
 public:
  // Streams 1-4 are GenerateInputs' own (state, textures, parameters, vectors).
  InputDraw(uint64_t seed, uint64_t batch, uint64_t stream);
  ~InputDraw();
  InputDraw(const InputDraw&) = delete;
  InputDraw& operator=(const InputDraw&) = delete;

  // A random batch's component: uniform in [-4, 4], a multiple of 0.5, log-scale in
  // 1e-4..1e4, or an edge value; with `finite`, one of FiniteEdgeValues().
  float Mixture(bool finite);
  float Uniform(float lo, float hi);
  int Below(int n);                     // n > 0
  GlState State();                      // a random well-conditioned GL state, as a batch's
  Texture TextureOf(TexTarget target);  // as a batch draws one for `target`

 private:
  std::unique_ptr<gen::Rng> rng_;
};

// EdgeValues() without the non-finite, denormal and huge (beyond 2^32) ones: GLSL 1.10
// section 4.1.4 asks no more of an implementation than OpenGL's precision (OpenGL 2.0
// section 2.1.1: about 1 part in 1e5, magnitudes to 2^32), so these are what every engine
// must compute alike.
const std::vector<float>& FiniteEdgeValues();

// "2D 4x4 linear repeat", "3D 4x8x4 ...", "CUBE 8x8 ...", with "depth compare lequal
// luminance" for depth textures: a texture as the disagreement reports describe it.
std::string DescribeTexture(const Texture& t);

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
