// Running GLSL 1.10 and 1.20 shaders on Mesa (`arbiter exec` of a .vert, a .frag or a pair):
// the same contexts, textures, GL state and worker process as the ARB executor (exec.h),
// one point per input vector. A vertex shader's outputs are captured with transform
// feedback (exact, before any clamping); a fragment shader's are read from RGBA32F colour
// attachments, its gl_FragDepth from a DEPTH32F depth buffer and its discard from the
// stencil buffer. docs/exec.md, "GLSL shaders".
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "arbiter/arbvp/exec.h"
#include "arbiter/glsl/reflect.h"
#include "arbiter/runtime/exec.h"
#include "arbiter/runtime/worker.h"

namespace arbiter::runtime {

// The shaders' texts (checked by arbiter first); an empty text is a stage not given. Each
// given stage comes with arbiter's reflection of it (the outputs read back, the inputs fed).
struct GlslShaders {
  std::string vertex;
  std::string fragment;
  const glsl::Reflection* vertex_reflection = nullptr;
  const glsl::Reflection* fragment_reflection = nullptr;
};

// One input of the run a --set may name: a vertex attribute (built-in or user), or, for a
// fragment shader alone, what reaches it from the vertex stage (gl_Color, gl_TexCoord[n],
// gl_FogFragCoord, gl_FragCoord.z, user varyings).
struct GlslInputSlot {
  std::string name;         // "gl_Vertex", "tangent", "gl_TexCoord[1]", "light[2]", "m"
  std::string type;         // "vec4", "float", "mat3"
  int components = 4;       // numbers the slot holds (a mat3: 9)
  int min_components = 4;   // fewer may be given to a built-in vec4: (0,0,0,1) fills the rest
  bool read = false;        // the shader statically reads it
  std::vector<float> fill;  // the value when not set (components numbers)
};

// The inputs of a run of `vertex` (may be null) and `fragment` (may be null), from arbiter's
// reflection of the shaders: attributes when there is a vertex shader, else the fragment
// shader's inputs.
std::vector<GlslInputSlot> GlslInputSlots(const glsl::Reflection* vertex,
                                          const glsl::Reflection* fragment);

struct GlslExecInputs {
  arbvp::GlState state;                    // --state (the ARB exec's names and upload)
  std::map<int, arbvp::Texture> textures;  // by texture image unit
  // --uniform NAME=V1,.. in order: NAME as GL names a uniform ("lightDir", "light.pos", "w"
  // for a whole array, "w[2]" for an element). Matrices column by column, as GLSL's
  // constructors take them.
  std::vector<std::pair<std::string, std::vector<float>>> uniforms;
  // Uniforms the shaders declare (arbiter's reflection): one the user sets that Mesa finds
  // inactive is a note, not an error.
  std::vector<std::string> declared_uniforms;
  // Per vector, the value of every slot (GlslInputSlots, fills included) by name.
  std::vector<std::map<std::string, std::vector<float>>> vectors;
  std::vector<GlslInputSlot> slots;
};

// Parses "NAME=V1,V2,.." as a --set of one of `slots` (NAME with its index, e.g.
// "gl_TexCoord[1]") into `values` (padded with the slot's fill). False with a lower-case
// reason for an unknown name or a wrong number of values.
[[nodiscard]] bool ParseGlslSet(const std::vector<GlslInputSlot>& slots,
                                std::string_view assignment, std::string* name,
                                std::vector<float>* values, std::string* error);
// "NAME=V1,.." as a --uniform (any count of numbers; Mesa's program checks it).
[[nodiscard]] bool ParseGlslUniform(std::string_view assignment, std::string* name,
                                    std::vector<float>* values, std::string* error);

// The JSON vectors file of a GLSL run: {"set": {NAME: [..]}, "uniforms": {NAME: [..]},
// "textures": {..as for ARB..}, "vectors": [{NAME: [..]}, ..]}; a "set" name that starts with
// "state." is GL state. Fills inputs->vectors (one per entry of "vectors", at least one).
[[nodiscard]] bool ParseGlslVectorsJson(std::string_view text, GlslExecInputs* inputs,
                                        std::string* error);

// One output of one vector.
struct GlslOutput {
  std::string name;   // "gl_Position", "gl_TexCoord[1]", "normal_eye", "w[2]", "gl_FragData[1]"
  std::string stage;  // "vertex" or "fragment"
  std::string type;   // "vec4", "float", "mat3"
  std::vector<float> value;  // matrices column by column
};

struct GlslVectorResult {
  std::vector<GlslOutput> outputs;  // vertex outputs, then fragment outputs
  bool discarded = false;           // the fragment shader discarded (no fragment outputs)
};

struct GlslRunResult {
  std::string description;  // "softpipe, 4.5 (Compatibility Profile) Mesa 22.3.6 (osmesa)"
  std::vector<GlslVectorResult> vectors;
  // "uniform lightDir not set: read as zero", ...
  std::vector<std::string> notes;
  // Set when a --uniform names no uniform or has the wrong number of values: nothing ran.
  std::string usage_error;
};

// Runs the shaders in this process (see RunGlslInWorker). False (with `error`) when Mesa
// rejects a shader or the GL fails.
[[nodiscard]] bool RunGlsl(const ExecOptions& options, const GlslShaders& shaders,
                           const GlslExecInputs& inputs, GlslRunResult* result, std::string* error);

// RunGlsl in a worker process (worker.h): a driver crash or hang becomes an error.
WorkerStatus RunGlslInWorker(const ExecOptions& options, const WorkerLimits& limits,
                             const GlslShaders& shaders, const GlslExecInputs& inputs,
                             GlslRunResult* result, std::string* error);

// The results as JSON: [{"discarded": bool, "outputs": [{"name", "stage", "type", "value"}]}],
// floats as arbvp::FloatToJson writes them.
nlohmann::ordered_json GlslResultsToJson(const std::vector<GlslVectorResult>& results);

// A whole run's result as JSON and back (what a worker process carries out): floats as
// FloatToJson writes them. False when `j` is not such an object.
nlohmann::ordered_json GlslRunResultToJson(const GlslRunResult& result);
[[nodiscard]] bool GlslRunResultFromJson(const nlohmann::json& j, GlslRunResult* result);

}  // namespace arbiter::runtime
