// GenerateGlslInputs: the edge batch and the random batches of a GLSL subject, drawn with
// arbvp's portable random source (arbvp::InputDraw) from arbiter's reflection of the shaders.
#include "arbiter/arbvp/generate.h"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>
#include <set>

#include "glsl_verify/internal.h"

namespace arbiter::runtime {
namespace glsl_verify {

int BasicComponents(const std::string& type) {
  static const std::map<std::string, int> kSizes = {
      {"float", 1},   {"vec2", 2},   {"vec3", 3},   {"vec4", 4},   {"int", 1},    {"ivec2", 2},
      {"ivec3", 3},   {"ivec4", 4},  {"bool", 1},   {"bvec2", 2},  {"bvec3", 3},  {"bvec4", 4},
      {"mat2", 4},    {"mat3", 9},   {"mat4", 16},  {"mat2x3", 6}, {"mat2x4", 8}, {"mat3x2", 6},
      {"mat3x4", 12}, {"mat4x2", 8}, {"mat4x3", 12}};
  auto it = kSizes.find(type);
  return it == kSizes.end() ? 0 : it->second;
}

namespace {

std::string Trim(std::string_view s) {
  size_t b = s.find_first_not_of(" \t\n");
  size_t e = s.find_last_not_of(" \t\n");
  return b == std::string_view::npos ? std::string() : std::string(s.substr(b, e - b + 1));
}

// The members of "struct S { vec4 a; float b[3]; struct T { .. } c; }": (type, name, size).
struct Member {
  std::string type;
  std::string name;
  int array_size = 0;
};
std::vector<Member> Members(std::string_view type) {
  std::vector<Member> out;
  size_t open = type.find('{');
  size_t close = type.rfind('}');
  if (open == std::string_view::npos || close == std::string_view::npos) return out;
  std::string_view body = type.substr(open + 1, close - open - 1);
  int depth = 0;
  size_t start = 0;
  for (size_t i = 0; i < body.size(); ++i) {
    if (body[i] == '{') ++depth;
    if (body[i] == '}') --depth;
    if (body[i] != ';' || depth != 0) continue;
    std::string decl = Trim(body.substr(start, i - start));
    start = i + 1;
    Member m;
    size_t bracket = decl.rfind('[');
    if (bracket != std::string::npos && decl.back() == ']') {
      m.array_size = std::atoi(decl.c_str() + bracket + 1);
      decl = Trim(decl.substr(0, bracket));
    }
    size_t space = decl.find_last_of(" }");
    if (space == std::string::npos) continue;
    m.name = Trim(decl.substr(space + 1));
    m.type = Trim(decl.substr(0, decl[space] == '}' ? space + 1 : space));
    out.push_back(m);
  }
  return out;
}

}  // namespace

void ExpandUniform(const std::string& name, const std::string& type, int array_size,
                   std::vector<UniformLeaf>* leaves) {
  if (type.rfind("struct", 0) == 0) {
    const std::vector<Member> members = Members(type);
    for (int i = 0; i < std::max(array_size, 1); ++i) {
      const std::string base = array_size > 0 ? fmt::format("{}[{}]", name, i) : name;
      for (const Member& m : members) {
        ExpandUniform(base + "." + m.name, m.type, m.array_size, leaves);
      }
    }
    return;
  }
  // Arrays element by element: Mesa keeps only the elements up to the last one used, and an
  // element it dropped is a note, where too many values for the array would be an error.
  for (int i = 0; i < std::max(array_size, 1); ++i) {
    UniformLeaf leaf;
    leaf.name = array_size > 0 ? fmt::format("{}[{}]", name, i) : name;
    leaf.type = type;
    leaf.components = std::max(BasicComponents(type), 1);
    leaves->push_back(leaf);
  }
}

namespace {

// The k-th (mod 16) stride coprime with n: stepping by it visits every edge value.
size_t Stride(size_t k, size_t n) {
  size_t want = k % 16;
  for (size_t s = 1;; ++s) {
    if (std::gcd(s, n) != 1) continue;
    if (want-- == 0) return s;
  }
}

float EdgeAt(size_t v, size_t k) {
  const std::vector<float>& edge = arbvp::FiniteEdgeValues();
  const size_t n = edge.size();
  return edge[(v * Stride(k, n) + 7 * k) % n];
}

// Inputs GL keeps in [0, 1]: the colours a fragment shader reads were clamped by the vertex
// stage (GL 2.0 section 2.14.6, CLAMP_VERTEX_COLOR).
bool IsClampedColor(const std::string& slot) {
  return slot == "gl_Color" || slot == "gl_SecondaryColor";
}

// The texture target a sampler type reads.
bool TargetOf(const std::string& sampler, arbvp::TexTarget* target) {
  static const std::map<std::string, arbvp::TexTarget> kTargets = {
      {"sampler1D", arbvp::TexTarget::Tex1D},
      {"sampler2D", arbvp::TexTarget::Tex2D},
      {"sampler3D", arbvp::TexTarget::Tex3D},
      {"samplerCube", arbvp::TexTarget::Cube},
      {"sampler2DRect", arbvp::TexTarget::Rect},
      {"sampler1DShadow", arbvp::TexTarget::Shadow1D},
      {"sampler2DShadow", arbvp::TexTarget::Shadow2D},
      {"sampler2DRectShadow", arbvp::TexTarget::ShadowRect},
  };
  auto it = kTargets.find(sampler);
  if (it == kTargets.end()) return false;
  *target = it->second;
  return true;
}

// Streams of InputDraw beyond GenerateInputs' own four.
enum : uint64_t { kStreamVectors = 11, kStreamUniforms = 12, kStreamTextures = 13 };

bool MakeBatch(const GlslVerifySubject& subject, const std::vector<GlslInputSlot>& slots,
               uint64_t seed, uint64_t batch, size_t count, GlslBatch* out, std::string* error) {
  const bool edge = batch == 0;
  GlslExecInputs& in = out->inputs;
  in.slots = slots;
  arbvp::InputDraw state_draw(seed, batch, 1);
  in.state = state_draw.State();
  // Clipping is fixed-function work, not the shader's: with a plane enabled the engines would
  // drop points instead of running the fragment shader (gl_ClipVertex is compared as an
  // output all the same).
  in.state.clip_enabled.fill(false);
  // Uniforms and samplers of both stages, each name once.
  arbvp::InputDraw uniform_draw(seed, batch, kStreamUniforms);
  arbvp::InputDraw texture_draw(seed, batch, kStreamTextures);
  std::set<std::string> seen;
  int unit = 0;
  size_t k = 0;
  for (const glsl::Reflection* r : {subject.vertex_reflection, subject.fragment_reflection}) {
    if (r == nullptr) continue;
    for (const glsl::ReflectedVariable& u : r->uniforms) {
      if (!seen.insert(u.name).second) continue;
      in.declared_uniforms.push_back(u.name);
      std::vector<UniformLeaf> leaves;
      ExpandUniform(u.name, u.type, u.array_size, &leaves);
      for (const UniformLeaf& leaf : leaves) {
        if (BasicComponents(leaf.type) == 0) {
          *error =
              fmt::format("uniform {} has a type verify cannot fill: {}", leaf.name, leaf.type);
          return false;
        }
        const bool is_int =
            leaf.type.find("int") != std::string::npos || leaf.type.rfind("ivec", 0) == 0;
        const bool is_bool = leaf.type.rfind("bool", 0) == 0 || leaf.type.rfind("bvec", 0) == 0;
        std::vector<float> values;
        for (int i = 0; i < leaf.components; ++i, ++k) {
          // Integers small enough to count loops and index the arrays they usually index.
          if (is_bool) {
            values.push_back(static_cast<float>(edge ? (k % 2) : uniform_draw.Below(2)));
          } else if (is_int) {
            values.push_back(static_cast<float>(edge ? (k % 4) : uniform_draw.Below(4)));
          } else {
            values.push_back(edge ? EdgeAt(k % 64, k + 40) : uniform_draw.Mixture(true));
          }
        }
        in.uniforms.emplace_back(leaf.name, std::move(values));
        out->float_uniforms.push_back(!is_int && !is_bool);
      }
    }
    for (const glsl::ReflectedVariable& s : r->samplers) {
      if (!seen.insert(s.name).second) continue;
      in.declared_uniforms.push_back(s.name);
      arbvp::TexTarget target;
      if (!TargetOf(s.type, &target)) {
        *error = fmt::format("sampler {} has a type verify cannot fill: {}", s.name, s.type);
        return false;
      }
      std::vector<float> units;
      for (int i = 0; i < std::max(s.array_size, 1); ++i) {
        arbvp::Texture t = texture_draw.TextureOf(target);
        // GL 2.0 filters a cube map within one face; llvmpipe and lavapipe filter across the
        // edges (seamless). Without a reference to tell which engine keeps to GL, cube maps
        // are sampled NEAREST (the ARB verify names the deviation: llvmpipe-cube-edge).
        if (target == arbvp::TexTarget::Cube) t.filter = arbvp::TexFilter::Nearest;
        // A depth comparison filtered LINEAR is the implementation's to choose, "a value in
        // the range [0, 1] proportional to the number of comparison passes" (GL 2.0 section
        // 3.8.14): compared NEAREST it is exact.
        if (t.compare) t.filter = arbvp::TexFilter::Nearest;
        in.textures[unit] = std::move(t);
        units.push_back(static_cast<float>(unit++));
      }
      in.uniforms.emplace_back(s.name, std::move(units));
      out->float_uniforms.push_back(false);
    }
  }
  // The vectors: every input slot the shaders read.
  arbvp::InputDraw vector_draw(seed, batch, kStreamVectors);
  for (size_t v = 0; v < count; ++v) {
    std::map<std::string, std::vector<float>> values;
    for (size_t s = 0; s < slots.size(); ++s) {
      const GlslInputSlot& slot = slots[s];
      std::vector<float> value = slot.fill;
      if (slot.read) {
        for (size_t c = 0; c < value.size(); ++c) {
          const size_t key = 4 * s + c;
          if (slot.name == "gl_FragCoord.z") {
            // A window depth within the depth range (GL 2.0 section 2.11.1); the edge batch
            // takes both ends.
            const float near = in.state.depth_near;
            const float far = in.state.depth_far;
            value[c] = edge ? (v == 0   ? near
                               : v == 1 ? far
                                        : near + (far - near) * 0.5f)
                            : vector_draw.Uniform(std::min(near, far), std::max(near, far));
          } else if (IsClampedColor(slot.name)) {
            value[c] = edge ? std::clamp(std::fabs(EdgeAt(v, key)), 0.0f, 1.0f)
                            : vector_draw.Uniform(0.0f, 1.0f);
          } else {
            value[c] = edge ? EdgeAt(v, key) : vector_draw.Mixture(true);
          }
        }
      }
      values[slot.name] = std::move(value);
    }
    in.vectors.push_back(std::move(values));
  }
  return true;
}

}  // namespace
}  // namespace glsl_verify

std::vector<GlslBatch> GenerateGlslInputs(const GlslVerifySubject& subject,
                                          const arbvp::GenerateOptions& options,
                                          std::string* error) {
  const std::vector<GlslInputSlot> slots =
      GlslInputSlots(subject.vertex_reflection, subject.fragment_reflection);
  std::vector<GlslBatch> batches(1);
  batches[0].name = "edge";
  if (!glsl_verify::MakeBatch(subject, slots, options.seed, 0, arbvp::FiniteEdgeValues().size(),
                              &batches[0], error)) {
    return {};
  }
  constexpr size_t kBatchSize = 64;
  size_t remaining = static_cast<size_t>(std::max(options.random_vectors, 0));
  for (uint64_t b = 1; remaining > 0; ++b) {
    const size_t count = std::min(remaining, kBatchSize);
    remaining -= count;
    GlslBatch batch;
    batch.name = fmt::format("random {}", b);
    if (!glsl_verify::MakeBatch(subject, slots, options.seed, b, count, &batch, error)) return {};
    batches.push_back(std::move(batch));
  }
  return batches;
}

}  // namespace arbiter::runtime
