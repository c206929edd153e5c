// Pieces shared by the GLSL verify's files: the uniform leaves a generator fills, the probe
// (an instrumented copy of the shaders that reports the undefined behaviour it meets and the
// outputs it leaves unwritten) and the comparison of two engines' results.
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

#include "arbiter/glsl/hazards.h"
#include "arbiter/runtime/glsl_verify.h"

namespace arbiter::runtime::glsl_verify {

// One value a --uniform sets: a basic-typed uniform, an element of an array, or a member of
// a structure.
struct UniformLeaf {
  std::string name;  // "w[2]", "lights[1].color": arrays element by element
  std::string type;  // "vec4", "int"
  int components = 1;
};

// The leaves of a uniform of reflected type `type` (reflect.h's spelling, structures with
// their members) named `name`, with `array_size` elements (0: no array).
void ExpandUniform(const std::string& name, const std::string& type, int array_size,
                   std::vector<UniformLeaf>* leaves);

// Components of a basic GLSL type ("mat3": 9); 0 for what is not one (samplers, structures).
int BasicComponents(const std::string& type);

// The instrumented shaders and what their sites are.
struct Probe {
  bool ok = false;
  std::string why;  // why there is no probe (then ok is false)
  std::string vertex;
  std::string fragment;
  // Site n (the number the probe reports): the hazard and its stage's file.
  std::vector<glsl::Hazard> sites;
  // Original output name -> the probe's name for it (gl_FragColor -> gl_FragData[0]).
  std::map<std::string, std::string> renamed;
  // What the shader reads that the implementation chooses, whatever the inputs: every
  // disagreement of the subject is put down to it.
  std::set<std::string> static_causes;
};

// The uniform through which the probe's outputs start out (a value no shader computes by
// chance); two runs with different values show the outputs a path leaves unwritten.
inline constexpr const char* kSentinelUniform = "arb_probe_sentinel";
// Where the probe reports, per stage: a vertex varying, a fragment colour output. Each holds
// (kinds met as a sum of powers of two, the first site met or -1, 0, 0).
inline constexpr const char* kProbeVarying = "arb_probe";
// The probe reads every built-in state matrix through matrixCompMult with these (all ones but
// in the nudged run): the matrices GL derives from one another (an inverse, a product) are
// then perturbed apart, which the perturbation of the GL state itself cannot do.
inline constexpr const char* kNudge4Uniform = "arb_probe_nudge4";
inline constexpr const char* kNudge3Uniform = "arb_probe_nudge3";
inline constexpr const char* kProbeFragData = "gl_FragData[7]";

Probe MakeProbe(const GlslVerifySubject& subject);

// What the probe found for one vector: the hazard kinds met (bit k: HazardKind k) and the
// first site, or no probe result (discarded, or no probe).
struct ProbeFinding {
  bool known = false;
  unsigned kinds = 0;
  int site = -1;
};
ProbeFinding ReadProbe(const GlslVectorResult& result);

// "division by zero (GLSL 1.10 section 4.1.4) at a.frag:3:14"; several kinds are listed.
std::string DescribeFinding(const ProbeFinding& finding, const Probe& probe);

}  // namespace arbiter::runtime::glsl_verify
