// The engine-neutral table of GLSL 1.10/1.20 execution cases: shaders, inputs spelled as
// `arbiter exec` takes them, and the outputs the GLSL and GL specs give (never an engine's),
// each with the tolerance the specs allow. Run on every GLSL engine by glsl_case_test.cpp.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "arbiter/arbvp/exec.h"

namespace arbiter::glsl_cases {

// How a computed component is compared with the expected one.
//   Exact     the same value (NaN matches NaN; +0 matches -0: GLSL 1.20 4.1.4 asks only for
//             IEEE single precision's precision and range, and GL 2.0 2.1.1 for x + 0 = x):
//             what the specs define exactly on representable values
//   Relative  |got - want| <= bound * |want|: what the specs define only to an accuracy
//   Absolute  |got - want| <= bound: approximations whose value is (near) zero
enum class Tolerance : uint8_t { Exact, Relative, Absolute };

// GLSL 1.20 4.1.4 holds floating-point work to "the guidelines for precision established by
// the OpenGL 1.4 specification": GL 2.0 2.1.1 (the same text) asks that individual
// operations be "accurate to about 1 part in 10^5". GLSL 1.20 gives the built-in functions no
// precision of their own, so this is the bound of every approximated one.
inline constexpr float kGlPrecision = 1.0e-5f;

struct GlslExpect {
  size_t vector = 0;
  std::string name;          // the output: "gl_Position", "v", "gl_TexCoord[1]", "gl_FragData[1]"
  std::vector<float> value;  // every component of the output (a matN column by column)
  Tolerance tolerance = Tolerance::Exact;
  float bound = 0.0f;
};

struct GlslCase {
  std::string name;
  std::string spec;      // the clause the expected values come from
  std::string vertex;    // "" when the case runs a fragment shader alone
  std::string fragment;  // "" when the case runs a vertex shader alone
  size_t vectors = 1;
  // Per vector, --set assignments (vector i takes sets[i]): "gl_Vertex=1,2,3", "t=1,2".
  std::vector<std::vector<std::string>> sets;
  std::vector<std::string> uniforms;  // --uniform: "a=1,2,3,4", "light.pos=1,2,3"
  std::vector<std::string> state;     // --state: "state.matrix.modelview=..."
  std::vector<std::string> textures;  // --texture: "1=2d:gradient:2x2"
  // Textures built by hand (by unit), after `textures`.
  std::function<void(std::map<int, arbvp::Texture>&)> make_textures;
  std::vector<GlslExpect> expects;
  std::vector<size_t> discarded;  // vectors the fragment shader must discard
  // Non-empty: the Vulkan engine refuses the case with a not_applicable reason containing
  // this text (a documented limit of its lowering); empty: it must run the case.
  std::string vulkan_refusal;
};

// Every case.
const std::vector<GlslCase>& AllGlslCases();

// gtest prints a case by its name.
inline void PrintTo(const GlslCase& c, std::ostream* os) { *os << c.name; }

}  // namespace arbiter::glsl_cases
