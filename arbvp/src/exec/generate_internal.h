// Pieces shared by the input generator's files (generate.cpp, generate_state.cpp,
// describe_inputs.cpp): a portable random source, the random GL state and textures, and
// what a program reads.
#pragma once

#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "arbiter/arbvp/exec.h"
#include "arbiter/arbvp/ir.h"

namespace arbiter::arbvp::gen {

// Random numbers that are the same on every machine: the raw bits of std::mt19937_64 (which
// the C++ standard specifies exactly) and conversions written here (the standard's
// distributions differ between libraries).
class Rng {
 public:
  explicit Rng(uint64_t seed) : engine_(seed) {}
  uint64_t Bits() { return engine_(); }
  // Uniform in [0, 1) with 24 bits: exact as a float.
  float Unit();
  // Uniform in [lo, hi].
  float Uniform(float lo, float hi);
  // Uniform integer in [0, n), n > 0.
  int Below(int n);
  bool Coin() { return (Bits() >> 63) != 0; }

 private:
  std::mt19937_64 engine_;
};

// The seed of one independent stream of one batch, so that (for example) the state of a
// batch does not depend on how many attributes the program reads.
enum class Stream : uint64_t { State = 1, Textures = 2, Params = 3, Vectors = 4 };
uint64_t StreamSeed(uint64_t seed, uint64_t batch, Stream stream);

// A random GL state within what the engines model alike (generate_state.cpp): well
// conditioned matrices, colours in [0, 1], spot cutoffs in [0, 90], and so on.
GlState RandomState(Rng* rng);

// A random texture of the dimension `target` samples; shadow targets get a comparing depth
// texture.
Texture RandomTexture(TexTarget target, Rng* rng);

// The inputs a program reads.
struct ReadInputs {
  std::vector<Binding> attribs;                     // vertex or fragment attributes
  std::vector<Binding> params;                      // program.env, program.local and state bindings
  std::vector<std::pair<int, TexTarget>> textures;  // by unit; the first target sampled
};

// With `declared`, every attribute and parameter the program declares (a superset, what the
// generator fills); else the bindings instructions read (every element of a relative-addressed
// array), what the description lists. Both add what program options read implicitly
// (ARB_position_invariant, ARB_fog_*).
ReadInputs FindReadInputs(const Program& program, bool declared);

}  // namespace arbiter::arbvp::gen
