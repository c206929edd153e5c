// The input generator of `arbiter verify`: the edge batch (every input component a program
// reads cycles through EdgeValues()) and random batches (components from a mixture of
// uniform, half-integer, log-scale and edge values), each with its own random GL state,
// program parameters and textures (generate_state.cpp).
#include "arbiter/arbvp/generate.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <string>

#include "exec/generate_internal.h"

namespace arbiter::arbvp {
namespace gen {
namespace {

constexpr size_t kBatchSize = 64;  // one row of the readback framebuffer

Binding AttribBinding(BindingKind kind, VertexAttrib vertex, FragmentAttrib fragment) {
  Binding b;
  b.kind = kind;
  b.vertex_attrib = vertex;
  b.fragment_attrib = fragment;
  return b;
}

Binding StateBinding(StateItem item) {
  Binding b;
  b.kind = BindingKind::State;
  b.state = item;
  return b;
}

Binding MatrixRow(MatrixName matrix, uint8_t row) {
  Binding b = StateBinding(StateItem::MatrixRow);
  b.matrix = matrix;
  b.row = row;
  return b;
}

// What program options read without naming it (ARB_position_invariant: the position and
// the modelview and projection matrices; ARB_fog_*: the fog coordinate and fog state).
void AddImplicitReads(const Program& program, ReadInputs* r) {
  if (program.kind == ProgramKind::Vertex && program.HasOption(OptionId::PositionInvariant)) {
    r->attribs.push_back(
        AttribBinding(BindingKind::VertexAttrib, VertexAttrib::Position, FragmentAttrib::Color));
    for (uint8_t row = 0; row < 4; ++row) {
      r->params.push_back(MatrixRow(MatrixName::Modelview, row));
      r->params.push_back(MatrixRow(MatrixName::Projection, row));
    }
  }
  if (program.kind == ProgramKind::Fragment &&
      (program.HasOption(OptionId::FogLinear) || program.HasOption(OptionId::FogExp) ||
       program.HasOption(OptionId::FogExp2))) {
    r->attribs.push_back(AttribBinding(BindingKind::FragmentAttrib, VertexAttrib::Position,
                                       FragmentAttrib::FogCoord));
    r->params.push_back(StateBinding(StateItem::FogColor));
    r->params.push_back(StateBinding(StateItem::FogParams));
  }
}

}  // namespace

ReadInputs FindReadInputs(const Program& program, bool declared) {
  ReadInputs r;
  auto add_param = [&r](const Binding& b) {
    if (b.kind != BindingKind::Constant) r.params.push_back(b);
  };
  if (declared) {
    for (const Variable& var : program.vars) {
      if (var.kind == VarKind::Attrib)
        r.attribs.insert(r.attribs.end(), var.bindings.begin(), var.bindings.end());
      if (var.kind == VarKind::Param) {
        for (const Binding& b : var.bindings) add_param(b);
      }
    }
  } else {
    for (const Instruction& inst : program.instructions) {
      for (size_t s = 0; s < inst.src_count; ++s) {
        const SrcOperand& src = inst.src[s];
        if (src.var < 0 || static_cast<size_t>(src.var) >= program.vars.size()) continue;
        const Variable& var = program.vars[static_cast<size_t>(src.var)];
        if (var.kind == VarKind::Attrib) {
          // Every element of an attribute array read with relative addressing.
          r.attribs.insert(r.attribs.end(), var.bindings.begin(), var.bindings.end());
        } else if (var.kind == VarKind::Param && src.relative) {
          for (const Binding& b : var.bindings) add_param(b);
        } else if (var.kind == VarKind::Param) {
          size_t element = src.indexed ? static_cast<size_t>(src.index) : 0;
          if (element < var.bindings.size()) add_param(var.bindings[element]);
        }
      }
    }
  }
  AddImplicitReads(program, &r);
  for (const Instruction& inst : program.instructions) {
    if (GetOpcodeInfo(inst.op).signature != OpSignature::Sample) continue;
    // Two targets on one unit is an error the checker reports: keep the first.
    auto same_unit = [&inst](const auto& t) { return t.first == inst.tex_unit; };
    if (std::none_of(r.textures.begin(), r.textures.end(), same_unit)) {
      r.textures.emplace_back(inst.tex_unit, inst.target);
    }
  }
  std::stable_sort(r.textures.begin(), r.textures.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  return r;
}

namespace {

// One stored input vector a program reads and the mask of its components that reach the
// program. Ids are distinct per stored vector: each gets its own edge strides.
//   vertex:   0 position, 1 normal (xyz), 2 colour, 3 secondary colour (xyz: GL has no
//             secondary alpha), 4 fog coordinate (x), 8 + n texcoord[n], 16 + n attrib[n]
//   fragment: 0 colour, 1 secondary colour, 2 fog coordinate, 8 + n texcoord[n]
// Weights and matrix indices keep their defaults (no engine on Mesa models them).
using Fields = std::map<int, uint8_t>;

void AddField(const Binding& b, Fields* fields) {
  auto add = [fields](int id, uint8_t mask) { (*fields)[id] |= mask; };
  bool texcoord_ok = b.index >= 0 && b.index < kMaxTextureCoords;
  if (b.kind == BindingKind::VertexAttrib) {
    switch (b.vertex_attrib) {
      case VertexAttrib::Position:
        return add(0, 0xF);
      case VertexAttrib::Normal:
        return add(1, 0x7);
      case VertexAttrib::Color:
        return add(2, 0xF);
      case VertexAttrib::SecondaryColor:
        return add(3, 0x7);
      case VertexAttrib::FogCoord:
        return add(4, 0x1);
      case VertexAttrib::TexCoord:
        if (texcoord_ok) add(8 + b.index, 0xF);
        return;
      case VertexAttrib::Generic:
        if (b.index == 0) return add(0, 0xF);  // vertex.attrib[0] is the position
        if (b.index > 0 && b.index < kMaxGenericAttribs) add(16 + b.index, 0xF);
        return;
      case VertexAttrib::Weight:
      case VertexAttrib::MatrixIndex:
        return;
    }
  } else if (b.kind == BindingKind::FragmentAttrib) {
    switch (b.fragment_attrib) {
      case FragmentAttrib::Color:
        return add(0, 0xF);
      case FragmentAttrib::SecondaryColor:
        return add(1, 0xF);
      case FragmentAttrib::FogCoord:
        return add(2, 0x1);
      case FragmentAttrib::TexCoord:
        if (texcoord_ok) add(8 + b.index, 0xF);
        return;
      case FragmentAttrib::Position:
        return;  // the pixel and FragmentInput::depth, set for every vector
      case FragmentAttrib::Facing:
        return;  // every engine draws front-facing points
    }
  }
}

float* VertexComponent(VertexInput* in, int id, size_t c) {
  switch (id) {
    case 0:
      return &in->position[c];
    case 1:
      return &in->normal[c];
    case 2:
      return &in->color[c];
    case 3:
      return &in->secondary_color[c];
    case 4:
      return &in->fogcoord[c];
    default:
      break;
  }
  if (id < 16) return &in->texcoord[static_cast<size_t>(id - 8)][c];
  return &in->generic[static_cast<size_t>(id - 16)][c];
}

float* FragmentComponent(FragmentInput* in, int id, size_t c) {
  switch (id) {
    case 0:
      return &in->color[c];
    case 1:
      return &in->secondary_color[c];
    case 2:
      return &in->fogcoord;
    default:
      break;
  }
  return &in->texcoord[static_cast<size_t>(id - 8)][c];
}

// The k-th (mod 16) stride coprime with n: stepping by it visits every edge value.
size_t Stride(size_t k, size_t n) {
  size_t want = k % 16;
  for (size_t s = 1;; ++s) {
    if (std::gcd(s, n) != 1) continue;
    if (want-- == 0) return s;
  }
}

// The edge value for component c of field `id` in edge vector v.
float EdgeComponent(size_t v, int id, size_t c) {
  const std::vector<float>& edge = EdgeValues();
  size_t n = edge.size();
  size_t k = 4 * static_cast<size_t>(id) + c;
  return edge[(v * Stride(k, n) + 7 * k) % n];
}

// One random component: 55% uniform in [-4, 4]; 20% a multiple of 0.5 in [-4, 4] (exact
// values on equality and floor boundaries); 15% log-scale, sign * m * 10^e with e in
// [-4, 3] and m uniform in [1, 10) (magnitudes 1e-4 .. 1e4); 10% an edge value.
float MixtureValue(Rng* rng, bool finite = false) {
  static constexpr float kPow10[] = {1e-4f, 1e-3f, 1e-2f, 1e-1f, 1.0f, 1e1f, 1e2f, 1e3f};
  int pick = rng->Below(100);
  if (pick < 55) return rng->Uniform(-4.0f, 4.0f);
  if (pick < 75) return static_cast<float>(rng->Below(17) - 8) * 0.5f;
  if (pick < 90) {
    float sign = rng->Coin() ? -1.0f : 1.0f;
    float mantissa = 1.0f + 9.0f * rng->Unit();
    return sign * mantissa * kPow10[rng->Below(8)];
  }
  const std::vector<float>& edge = finite ? FiniteEdgeValues() : EdgeValues();
  return edge[static_cast<size_t>(rng->Below(static_cast<int>(edge.size())))];
}

// Draws `count` vectors: edge values (edge batch) or mixture values for every field.
std::vector<InputVector> MakeVectors(ProgramKind kind, bool fragment_depth, const Fields& fields,
                                     const GlState& state, size_t count, bool edge, Rng* rng) {
  std::vector<InputVector> vectors(count);
  for (size_t v = 0; v < count; ++v) {
    InputVector& in = vectors[v];
    for (const auto& [id, mask] : fields) {
      for (size_t c = 0; c < 4; ++c) {
        if (!(mask & (1u << c))) continue;
        float value = edge ? EdgeComponent(v, id, c) : MixtureValue(rng);
        *(kind == ProgramKind::Vertex ? VertexComponent(&in.vertex, id, c)
                                      : FragmentComponent(&in.fragment, id, c)) = value;
      }
    }
    if (!fragment_depth) continue;
    // Window depth within the depth range; the edge batch also takes both ends.
    if (edge && v == 0) {
      in.fragment.depth = state.depth_near;
    } else if (edge && v == 1) {
      in.fragment.depth = state.depth_far;
    } else {
      in.fragment.depth = rng->Uniform(state.depth_near, state.depth_far);
    }
  }
  return vectors;
}

// program.env and program.local of the program's kind: every index it declares a binding
// of (with relative-addressed arrays, every element).
void MakeParams(const Program& program, bool edge, Rng* rng, ExecInputs* inputs) {
  ProgramParameters& params =
      program.kind == ProgramKind::Vertex ? inputs->vertex_params : inputs->fragment_params;
  const std::vector<float>& edge_values = EdgeValues();
  for (const Binding& b : FindReadInputs(program, true).params) {
    bool local = b.kind == BindingKind::ProgramLocal;
    if (!local && b.kind != BindingKind::ProgramEnv) continue;
    std::map<int, Vec4>& map = local ? params.local : params.env;
    if (map.count(b.index)) continue;
    Vec4 value{};
    for (size_t c = 0; c < 4; ++c) {
      size_t k = 4 * static_cast<size_t>(b.index) + c + (local ? 13 : 0);
      value[c] = edge ? edge_values[k % edge_values.size()] : MixtureValue(rng);
    }
    map[b.index] = value;
  }
}

ExecInputs MakeBatch(const Program* vertex, const Program* fragment, uint64_t seed, uint64_t batch,
                     size_t count) {
  const bool edge = batch == 0;
  ExecInputs inputs;
  Rng state_rng(StreamSeed(seed, batch, Stream::State));
  inputs.state = RandomState(&state_rng);
  Rng param_rng(StreamSeed(seed, batch, Stream::Params));
  for (const Program* p : {vertex, fragment}) {
    if (p) MakeParams(*p, edge, &param_rng, &inputs);
  }
  Rng texture_rng(StreamSeed(seed, batch, Stream::Textures));
  for (const Program* p : {vertex, fragment}) {
    if (!p) continue;
    for (const auto& [unit, target] : FindReadInputs(*p, true).textures) {
      if (!inputs.textures.count(unit)) inputs.textures[unit] = RandomTexture(target, &texture_rng);
    }
  }
  // A pair takes its fragment inputs from the vertex program.
  const Program& attrib_program = vertex ? *vertex : *fragment;
  Fields fields;
  for (const Binding& b : FindReadInputs(attrib_program, true).attribs) AddField(b, &fields);
  Rng vector_rng(StreamSeed(seed, batch, Stream::Vectors));
  inputs.vectors = MakeVectors(attrib_program.kind, vertex == nullptr, fields, inputs.state, count,
                               edge, &vector_rng);
  return inputs;
}

}  // namespace
}  // namespace gen

const std::vector<float>& EdgeValues() {
  constexpr float kInf = std::numeric_limits<float>::infinity();
  constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
  constexpr float kPi = 3.14159274f;  // pi rounded to float
  // clang-format off
  static const std::vector<float> kValues = {
      0.0f, -0.0f,                        // signed zeros
      1.0f, -1.0f, 0.5f, -0.5f,           // units and halves: SGE/SLT/FLR/FRC edges
      2.0f, -2.0f, 3.0f, 0.25f,           // small exact values
      1e-3f, -1e-3f, 100.0f, -100.0f,     // small and large magnitudes
      1e10f, -1e10f,                      // beyond float's exact integers
      127.5f, -128.0f,                    // LIT's exponent clamp (+-128)
      kPi, -kPi,                          // SIN/COS/SCS arguments
      1e-40f, -1e-40f,                    // denormals
      3e38f, -3e38f,                      // near FLT_MAX: products overflow
      kInf, -kInf, kNan,                  // non-finite
      1.5f, -1.5f, 0.75f, 16.0f, 1e-20f,  // halves for rounding, a power of two, a tiny normal
  };
  // clang-format on
  return kValues;
}

const std::vector<float>& FiniteEdgeValues() {
  static const std::vector<float> kValues = [] {
    std::vector<float> out;
    for (float v : EdgeValues()) {
      const float a = std::fabs(v);
      if (std::isfinite(v) && (v == 0.0f || a >= std::numeric_limits<float>::min()) &&
          a <= 0x1p32f) {
        out.push_back(v);
      }
    }
    return out;
  }();
  return kValues;
}

InputDraw::InputDraw(uint64_t seed, uint64_t batch, uint64_t stream)
    : rng_(std::make_unique<gen::Rng>(
          gen::StreamSeed(seed, batch, static_cast<gen::Stream>(stream)))) {}
InputDraw::~InputDraw() = default;
float InputDraw::Mixture(bool finite) { return gen::MixtureValue(rng_.get(), finite); }
float InputDraw::Uniform(float lo, float hi) { return rng_->Uniform(lo, hi); }
int InputDraw::Below(int n) { return rng_->Below(n); }
GlState InputDraw::State() { return gen::RandomState(rng_.get()); }
Texture InputDraw::TextureOf(TexTarget target) { return gen::RandomTexture(target, rng_.get()); }

std::vector<InputBatch> GenerateInputs(const Program* vertex, const Program* fragment,
                                       const GenerateOptions& options) {
  assert(vertex || fragment);
  std::vector<InputBatch> batches;
  if (!vertex && !fragment) return batches;
  batches.push_back(
      {"edge", gen::MakeBatch(vertex, fragment, options.seed, 0, EdgeValues().size())});
  size_t remaining = options.random_vectors > 0 ? static_cast<size_t>(options.random_vectors) : 0;
  for (uint64_t batch = 1; remaining > 0; ++batch) {
    size_t count = std::min(remaining, gen::kBatchSize);
    remaining -= count;
    batches.push_back({"random " + std::to_string(batch),
                       gen::MakeBatch(vertex, fragment, options.seed, batch, count)});
  }
  return batches;
}

}  // namespace arbiter::arbvp
