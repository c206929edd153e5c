// The operations of a GLSL 1.10/1.20 shader whose result the specification leaves undefined
// for some operands (division by zero, pow of a negative base, an array index out of range,
// ...): found in glslang's AST, so that `arbiter verify` can instrument each one and name
// the undefined behaviour a disagreement comes from (docs/verify.md, "GLSL shaders").
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "arbiter/compiler/source.h"
#include "arbiter/glsl/check.h"

namespace arbiter::glsl {

// X(name, what, spec): each kind once, in report order.
#define ARBITER_GLSL_HAZARDS(X)                                                                \
  X(Division, "division by zero", "GLSL 1.10 section 4.1.4")                                   \
  X(Mod, "mod(x, y) with y = 0 (x - y * floor(x / y) divides by zero)", "GLSL 1.10 8.3")       \
  X(Pow, "pow(x, y) with x < 0, or x = 0 and y <= 0", "GLSL 1.10 section 8.2")                 \
  X(Log, "log or log2 of x <= 0", "GLSL 1.10 section 8.2")                                     \
  X(Sqrt, "sqrt of x < 0", "GLSL 1.10 section 8.2")                                            \
  X(InverseSqrt, "inversesqrt of x <= 0", "GLSL 1.10 section 8.2")                             \
  X(AsinAcos, "asin or acos of |x| > 1", "GLSL 1.10 section 8.1")                              \
  X(Atan, "atan(y, x) with x = y = 0", "GLSL 1.10 section 8.1")                                \
  X(Normalize, "normalize of a zero vector (x / length(x) divides by zero)",                   \
    "GLSL 1.10 section 8.4")                                                                   \
  X(Clamp, "clamp(x, minVal, maxVal) with minVal > maxVal", "GLSL 1.10 section 8.3")           \
  X(Smoothstep, "smoothstep(edge0, edge1, x) with edge0 >= edge1", "GLSL 3.30 section 8.3")    \
  X(Index, "an array, vector or matrix index out of range", "GLSL 1.10 sections 5.5, 5.7")     \
  X(Projection, "a projective texture lookup with q = 0 (the coordinates divide by it)",       \
    "GLSL 1.10 section 8.7")                                                                   \
  X(CubeFace, "a cube map lookup whose direction's largest components tie (no face is named)", \
    "OpenGL 2.0 section 3.8.6")

enum class HazardKind : uint8_t {
#define ARBITER_GLSL_HAZARD_ENUM(name, what, spec) name,
  ARBITER_GLSL_HAZARDS(ARBITER_GLSL_HAZARD_ENUM)
#undef ARBITER_GLSL_HAZARD_ENUM
};

struct HazardInfo {
  HazardKind kind;
  std::string_view name;  // "Division"
  std::string_view what;  // "division by zero"
  std::string_view spec;  // "GLSL 1.10 section 4.1.4"
};
const std::vector<HazardInfo>& AllHazards();
const HazardInfo& GetHazardInfo(HazardKind kind);

// One operation that may be undefined.
struct Hazard {
  HazardKind kind = HazardKind::Division;
  // The operator ('/' of a division, "/=" of a compound one, '[' of an index) or the built-in
  // function's name (a texture lookup's: its coordinates are the second argument). File null
  // when glslang gives no place in the sources (a macro's expansion may then be anywhere).
  const compiler::SourceFile* file = nullptr;
  compiler::Range range;
  bool compound = false;  // "/=": the right operand is the rest of the assignment
  int size = 0;           // Index: the elements of what is indexed
};

// The hazards of the stage's shader (sources as CheckShader takes them), in source order. The
// shader must have been checked without errors (CheckShader); an empty list otherwise.
std::vector<Hazard> FindHazards(Stage stage,
                                const std::vector<const compiler::SourceFile*>& sources,
                                const CheckOptions& options = {});

}  // namespace arbiter::glsl
