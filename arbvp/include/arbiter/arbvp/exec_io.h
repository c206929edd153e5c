// Reading the execution model from text (the `--set`/`--state`/`--texture` flags of
// `arbiter exec` and its JSON vectors file) and writing results as JSON.
//
// Assignments name what they set the way the ARB specs spell bindings:
//   vertex.position / weight / normal / color / color.secondary / fogcoord /
//     texcoord[n] / matrixindex / attrib[n]                       (per vector)
//   fragment.color / color.secondary / texcoord[n] / fogcoord / depth (per vector)
//   program.env[i] / program.local[i]        (both targets; prefix "vertex." or "fragment."
//                                             for one: vertex.program.local[3])
//   state.matrix.modelview / projection / texture[n] / program[n]   (16 numbers, row-major:
//                                             the first four are row[0] as ARB reads it)
//   state.material[.front|.back].ambient / diffuse / specular / emission / shininess
//   state.light[n].ambient / diffuse / specular / position / spot.direction (3) /
//     spot.exponent / spot.cutoff / attenuation (3: constant, linear, quadratic)
//   state.lightmodel.ambient
//   state.texgen[n].eye.s|t|r|q / object.s|t|r|q
//   state.fog.color / density / start / end
//   state.clip[n].plane
//   state.point.size / min / max / fade / attenuation (3)
//   state.texenv[n].color
//   state.depth.range (2: near, far)
// A vector value takes 1 to 4 numbers; missing components keep their GL defaults' fill
// ((0,0,0,1) rule). Numbers are decimal floats or inf, -inf, nan.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "arbiter/arbvp/exec.h"

namespace arbiter::arbvp {

// Applies "name=v1,v2,..." to `inputs`. Per-vector names apply to `vector`; everything else
// to the shared state. On error returns false with a lower-case reason.
[[nodiscard]] bool ApplyAssignment(std::string_view assignment, ExecInputs* inputs,
                                   InputVector* vector, std::string* error);

// Parses a texture flag "UNIT=TARGET:PATTERN[:WxH[xD]][:FILTER][:WRAP]" (TARGET 1d 2d 3d cube
// rect, PATTERN a name of MakePatternTexture, FILTER nearest|linear, WRAP repeat|clamp|mirror,
// e.g. "0=2d:checker:4x4:linear") into inputs->textures.
[[nodiscard]] bool ApplyTextureFlag(std::string_view flag, ExecInputs* inputs, std::string* error);

// A generated texture: "checker" (white and opaque black texels alternating), "gradient"
// (texel centre coordinates in [0,1] as r, g, b; cube faces: b = (face + 0.5) / 6; a = 1),
// "depth-gradient" (a depth texture whose depth is the s texel centre, compare off), and
// "depth-gradient-compare" (the same with GL_COMPARE_R_TO_TEXTURE, LEQUAL). False for an
// unknown pattern.
[[nodiscard]] bool MakePatternTexture(std::string_view pattern, TexDim dim, int width, int height,
                                      int depth, Texture* texture);

// What a run is given that its programs never read, one warning each (for `arbiter exec`):
// an assignment of `assignments` ("name=values", as --set takes them) to an attribute or a
// program.env/local entry no program of the run reads (in a pair, fragment.* inputs come from
// the vertex program), a texture on a unit no instruction samples or of another target than
// the one sampled, and a sampled unit without a texture. State (state.*) is not judged: a
// program reads it through derived state too (state.lightprod).
std::vector<std::string> UnusedInputWarnings(const std::vector<const Program*>& programs,
                                             const std::vector<std::string>& assignments,
                                             const ExecInputs& inputs);

// The JSON vectors file:
//   { "set":      { "program.local[0]": [1,2,3,4], "state.fog.color": [1,0,0,1], ... },
//     "textures": { "0": { "target": "2d", "pattern": "checker", "size": [4,4],
//                          "filter": "linear", "wrap": "clamp" },
//                   "1": { "target": "2d", "size": [2,1], "texels": [r,g,b,a, ...],
//                          "depth": false, "compare": "lequal", "depth_mode": "luminance" } },
//     "vectors":  [ { "vertex.attrib[1]": [1,2,3,4] }, { "vertex.normal": [0,1,0] } ] }
// Values are numbers, arrays of numbers, or the strings "inf", "-inf", "nan". `inputs`
// keeps what was set before (flags apply on top).
[[nodiscard]] bool ParseVectorsJson(std::string_view text, ExecInputs* inputs, std::string* error);

// Results as JSON: one object per vector {"killed": bool, "outputs": [{"register", "value",
// "written", "undefined"}]}. Non-finite floats are the strings "inf", "-inf", "nan" (JSON
// has no spelling for them); -0 stays -0.0. `with_bindings` adds each register's binding as
// [result, index, face, secondary] (what the worker process sends back).
nlohmann::ordered_json ResultsToJson(const std::vector<VectorResult>& results,
                                     bool with_bindings = false);
// The inverse (used to carry results out of the worker process).
[[nodiscard]] bool ResultsFromJson(const nlohmann::json& json, std::vector<VectorResult>* results,
                                   std::string* error);

// A float as JSON: a number, or "inf", "-inf", "nan".
nlohmann::ordered_json FloatToJson(float value);
// The shortest text that reads back as the same float: "1", "-0", "0.1", "inf", "nan".
std::string FormatFloat(float value);
// Bitwise-equal floats, with every NaN equal to every NaN: what "same value" means for
// comparing engines exactly.
bool SameFloat(float a, float b);

// One component on which two engines' results differ.
struct Difference {
  size_t vector = 0;
  std::string reg;     // the register's name; empty for a kill difference
  int component = -1;  // 0..3; -1: the register (or the kill) as a whole
  float a = 0.0f;
  float b = 0.0f;
  std::string what;  // "killed by a only", "written by b only", "" for a value
};

// Compares two engines' results exactly (SameFloat) on every component both wrote and `a`
// does not tag undefined; kills and registers present on one side only differ too.
std::vector<Difference> CompareResults(const std::vector<VectorResult>& a,
                                       const std::vector<VectorResult>& b);

}  // namespace arbiter::arbvp
