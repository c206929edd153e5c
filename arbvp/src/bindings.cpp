// Canonical spellings of bindings, as the specs write them.
#include <fmt/format.h>

#include <array>
#include <bit>
#include <iterator>
#include <string_view>

#include "arbiter/arbvp/ir.h"
#include "arbiter/glstate/spelling.h"
#include "binding_key.h"

namespace arbiter::arbvp {
namespace {

std::string_view FaceName(Face face) { return face == Face::Back ? "back" : "front"; }

// How each state binding is spelled (state_items.def), as the specs write them: {f} is the
// face, {i} the index, {c} the texgen coordinate, {m} the matrix (its own spelling) and its
// modifier, {r} the row. StateName writes these; KeyOf keys exactly the fields a spelling
// shows (kStateFields), so equal names give equal keys.
constexpr auto kStateSpellings = [] {
  std::array<std::string_view, std::size(glstate::kStateItems)> spellings{};
  for (size_t i = 0; i < spellings.size(); ++i) spellings[i] = glstate::kStateItems[i].spelling;
  return spellings;
}();
constexpr auto kMatrixSpellings = [] {
  std::array<std::string_view, std::size(glstate::kStateMatrices)> spellings{};
  for (size_t i = 0; i < spellings.size(); ++i) spellings[i] = glstate::kStateMatrices[i].spelling;
  return spellings;
}();

// The selector fields a state binding's spelling shows.
struct StateFields {
  bool face = false;
  bool index = false;  // for a matrix row: where the matrix is numbered
  bool coord = false;
  bool matrix = false;  // matrix, modifier and row
};

constexpr bool Shows(std::string_view spelling, std::string_view field) {
  return spelling.find(field) != std::string_view::npos;
}

constexpr auto kStateFields = [] {
  std::array<StateFields, std::size(kStateSpellings)> fields{};
  for (size_t i = 0; i < fields.size(); ++i) {
    fields[i] = {Shows(kStateSpellings[i], "{f}"), Shows(kStateSpellings[i], "{i}"),
                 Shows(kStateSpellings[i], "{c}"), Shows(kStateSpellings[i], "{m}")};
  }
  return fields;
}();
constexpr auto kMatrixNumbered = [] {
  std::array<bool, std::size(kMatrixSpellings)> numbered{};
  for (size_t i = 0; i < numbered.size(); ++i) numbered[i] = Shows(kMatrixSpellings[i], "{i}");
  return numbered;
}();

StateFields StateNameFields(const Binding& b) {
  const size_t item = static_cast<size_t>(b.state);
  if (item >= kStateFields.size()) return {true, true, true, true};
  StateFields fields = kStateFields[item];
  if (fields.matrix) {
    const size_t matrix = static_cast<size_t>(b.matrix);
    fields.index = matrix >= kMatrixNumbered.size() || kMatrixNumbered[matrix];
  }
  return fields;
}

std::string StateName(const Binding& b) {
  if (static_cast<size_t>(b.state) >= std::size(kStateSpellings)) return "state.?";
  return glstate::StateSpelling(StateRefOf(b));
}

}  // namespace

glstate::StateRef StateRefOf(const Binding& b) {
  return {.item = b.state,
          .index = b.index,
          .face = b.face,
          .coord = b.coord,
          .matrix = b.matrix,
          .modifier = b.modifier,
          .row = b.row};
}

std::string BindingName(const Binding& b, ProgramKind kind) {
  switch (b.kind) {
    case BindingKind::VertexAttrib:
      switch (b.vertex_attrib) {
        case VertexAttrib::Position:
          return "vertex.position";
        case VertexAttrib::Weight:
          return fmt::format("vertex.weight[{}]", b.index);
        case VertexAttrib::Normal:
          return "vertex.normal";
        case VertexAttrib::Color:
          return "vertex.color.primary";
        case VertexAttrib::SecondaryColor:
          return "vertex.color.secondary";
        case VertexAttrib::FogCoord:
          return "vertex.fogcoord";
        case VertexAttrib::TexCoord:
          return fmt::format("vertex.texcoord[{}]", b.index);
        case VertexAttrib::MatrixIndex:
          return fmt::format("vertex.matrixindex[{}]", b.index);
        case VertexAttrib::Generic:
          return fmt::format("vertex.attrib[{}]", b.index);
      }
      break;
    case BindingKind::FragmentAttrib:
      switch (b.fragment_attrib) {
        case FragmentAttrib::Color:
          return "fragment.color.primary";
        case FragmentAttrib::SecondaryColor:
          return "fragment.color.secondary";
        case FragmentAttrib::TexCoord:
          return fmt::format("fragment.texcoord[{}]", b.index);
        case FragmentAttrib::FogCoord:
          return "fragment.fogcoord";
        case FragmentAttrib::Position:
          return "fragment.position";
        case FragmentAttrib::Facing:
          return "fragment.facing";
      }
      break;
    case BindingKind::Result:
      switch (b.result) {
        case ResultReg::Position:
          return "result.position";
        case ResultReg::Color:
          return fmt::format("result.color.{}.{}", FaceName(b.face),
                             b.secondary ? "secondary" : "primary");
        case ResultReg::FogCoord:
          return "result.fogcoord";
        case ResultReg::PointSize:
          return "result.pointsize";
        case ResultReg::TexCoord:
          return fmt::format("result.texcoord[{}]", b.index);
        case ResultReg::ClipDistance:
          return fmt::format("result.clip[{}]", b.index);
        case ResultReg::FragColor:
          return b.indexed ? fmt::format("result.color[{}]", b.index) : "result.color";
        case ResultReg::FragDepth:
          return "result.depth";
      }
      break;
    case BindingKind::State:
      return StateName(b);
    case BindingKind::ProgramEnv:
      return fmt::format("program.env[{}]", b.index);
    case BindingKind::ProgramLocal:
      return fmt::format("program.local[{}]", b.index);
    case BindingKind::Constant:
      return fmt::format("{{{}, {}, {}, {}}}", b.value[0], b.value[1], b.value[2], b.value[3]);
  }
  (void)kind;
  return "?";
}

namespace {

// Whether BindingName spells the index of a non-state binding.
bool NameHasIndex(const Binding& b) {
  switch (b.kind) {
    case BindingKind::VertexAttrib:
      return b.vertex_attrib == VertexAttrib::Weight || b.vertex_attrib == VertexAttrib::TexCoord ||
             b.vertex_attrib == VertexAttrib::MatrixIndex ||
             b.vertex_attrib == VertexAttrib::Generic;
    case BindingKind::FragmentAttrib:
      return b.fragment_attrib == FragmentAttrib::TexCoord;
    case BindingKind::Result:
      return b.result == ResultReg::TexCoord || b.result == ResultReg::ClipDistance ||
             (b.result == ResultReg::FragColor && b.indexed);
    case BindingKind::ProgramEnv:
    case BindingKind::ProgramLocal:
      return true;
    case BindingKind::State:
    case BindingKind::Constant:
      return false;
  }
  return true;
}

uint32_t FloatBits(float v, bool signed_zero) {
  return std::bit_cast<uint32_t>(signed_zero ? v : v + 0.0f);  // -0 + 0 is +0
}

}  // namespace

// Mirrors BindingName (and StateName's spellings): a field goes into the key only where the
// name spells it, so equal names give equal keys; and the name spells every field of the key
// distinctly, so different keys give different names. State fields come from the spellings
// themselves; keep NameHasIndex in step with BindingName for the others
// (tests/arbvp/front_end_test.cpp checks names and keys against each other).
BindingKey KeyOf(const Binding& b, bool signed_zero) {
  BindingKey key;
  auto& w = key.words;
  w[0] = static_cast<uint32_t>(b.kind);
  if (b.kind == BindingKind::Constant) {
    for (size_t i = 0; i < 4; ++i) w[i + 1] = FloatBits(b.value[i], signed_zero);
    return key;
  }
  uint32_t item = 0;
  uint32_t extra = 0;  // face, secondary, coordinate, matrix, modifier, row, indexed
  bool index = NameHasIndex(b);
  switch (b.kind) {
    case BindingKind::VertexAttrib:
      item = static_cast<uint32_t>(b.vertex_attrib);
      break;
    case BindingKind::FragmentAttrib:
      item = static_cast<uint32_t>(b.fragment_attrib);
      break;
    case BindingKind::Result:
      item = static_cast<uint32_t>(b.result);
      if (b.result == ResultReg::Color) {
        extra = static_cast<uint32_t>(b.face) | (b.secondary ? 2u : 0u);
      } else if (b.result == ResultReg::FragColor) {
        extra = b.indexed ? 1u : 0u;
      }
      break;
    case BindingKind::State: {
      item = static_cast<uint32_t>(b.state);
      StateFields f = StateNameFields(b);
      index = f.index;
      if (f.face) extra |= static_cast<uint32_t>(b.face);
      if (f.coord) extra |= uint32_t{b.coord} << 8;
      if (f.matrix) {
        extra |= (static_cast<uint32_t>(b.matrix) << 16) |
                 (static_cast<uint32_t>(b.modifier) << 20) | (uint32_t{b.row} << 24);
      }
      break;
    }
    case BindingKind::ProgramEnv:
    case BindingKind::ProgramLocal:
    case BindingKind::Constant:
      break;
  }
  w[1] = item;
  w[2] = extra;
  w[3] = index ? static_cast<uint32_t>(b.index) : 0u;
  return key;
}

size_t BindingKeyHash::operator()(const BindingKey& key) const {
  uint64_t hash = 0;
  for (uint32_t word : key.words) hash = (hash ^ word) * 0x9E3779B97F4A7C15ull;  // Fibonacci
  return static_cast<size_t>(hash ^ (hash >> 32));
}

int GenericAttribSlot(const Binding& b) {
  switch (b.vertex_attrib) {
    case VertexAttrib::Position:
      return 0;
    case VertexAttrib::Weight:
      return b.index == 0 ? 1 : -1;
    case VertexAttrib::Normal:
      return 2;
    case VertexAttrib::Color:
      return 3;
    case VertexAttrib::SecondaryColor:
      return 4;
    case VertexAttrib::FogCoord:
      return 5;
    case VertexAttrib::TexCoord:
      return 8 + b.index;
    case VertexAttrib::MatrixIndex:
      return -1;
    case VertexAttrib::Generic:
      return b.index;
  }
  return -1;
}

}  // namespace arbiter::arbvp
