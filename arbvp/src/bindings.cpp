// Canonical spellings of bindings, as the specs write them.
#include <fmt/format.h>

#include <bit>

#include "arbiter/arbvp/ir.h"
#include "binding_key.h"

namespace arbiter::arbvp {
namespace {

std::string_view FaceName(Face face) { return face == Face::Back ? "back" : "front"; }

std::string StateName(const Binding& b) {
  switch (b.state) {
    case StateItem::MaterialAmbient:
      return fmt::format("state.material.{}.ambient", FaceName(b.face));
    case StateItem::MaterialDiffuse:
      return fmt::format("state.material.{}.diffuse", FaceName(b.face));
    case StateItem::MaterialSpecular:
      return fmt::format("state.material.{}.specular", FaceName(b.face));
    case StateItem::MaterialEmission:
      return fmt::format("state.material.{}.emission", FaceName(b.face));
    case StateItem::MaterialShininess:
      return fmt::format("state.material.{}.shininess", FaceName(b.face));
    case StateItem::LightAmbient:
      return fmt::format("state.light[{}].ambient", b.index);
    case StateItem::LightDiffuse:
      return fmt::format("state.light[{}].diffuse", b.index);
    case StateItem::LightSpecular:
      return fmt::format("state.light[{}].specular", b.index);
    case StateItem::LightPosition:
      return fmt::format("state.light[{}].position", b.index);
    case StateItem::LightAttenuation:
      return fmt::format("state.light[{}].attenuation", b.index);
    case StateItem::LightSpotDirection:
      return fmt::format("state.light[{}].spot.direction", b.index);
    case StateItem::LightHalf:
      return fmt::format("state.light[{}].half", b.index);
    case StateItem::LightModelAmbient:
      return "state.lightmodel.ambient";
    case StateItem::LightModelSceneColor:
      return fmt::format("state.lightmodel.{}.scenecolor", FaceName(b.face));
    case StateItem::LightProdAmbient:
      return fmt::format("state.lightprod[{}].{}.ambient", b.index, FaceName(b.face));
    case StateItem::LightProdDiffuse:
      return fmt::format("state.lightprod[{}].{}.diffuse", b.index, FaceName(b.face));
    case StateItem::LightProdSpecular:
      return fmt::format("state.lightprod[{}].{}.specular", b.index, FaceName(b.face));
    case StateItem::TexGenEye:
    case StateItem::TexGenObject:
      return fmt::format("state.texgen[{}].{}.{}", b.index,
                         b.state == StateItem::TexGenEye ? "eye" : "object", "strq"[b.coord]);
    case StateItem::FogColor:
      return "state.fog.color";
    case StateItem::FogParams:
      return "state.fog.params";
    case StateItem::ClipPlane:
      return fmt::format("state.clip[{}].plane", b.index);
    case StateItem::PointSize:
      return "state.point.size";
    case StateItem::PointAttenuation:
      return "state.point.attenuation";
    case StateItem::TexEnvColor:
      return fmt::format("state.texenv[{}].color", b.index);
    case StateItem::DepthRange:
      return "state.depth.range";
    case StateItem::MatrixRow: {
      std::string name;
      switch (b.matrix) {
        case MatrixName::Modelview:
          name = fmt::format("modelview[{}]", b.index);
          break;
        case MatrixName::Projection:
          name = "projection";
          break;
        case MatrixName::Mvp:
          name = "mvp";
          break;
        case MatrixName::Texture:
          name = fmt::format("texture[{}]", b.index);
          break;
        case MatrixName::Palette:
          name = fmt::format("palette[{}]", b.index);
          break;
        case MatrixName::Program:
          name = fmt::format("program[{}]", b.index);
          break;
      }
      std::string_view modifier;
      switch (b.modifier) {
        case MatrixModifier::None:
          break;
        case MatrixModifier::Inverse:
          modifier = ".inverse";
          break;
        case MatrixModifier::Transpose:
          modifier = ".transpose";
          break;
        case MatrixModifier::InvTrans:
          modifier = ".invtrans";
          break;
      }
      return fmt::format("state.matrix.{}{}.row[{}]", name, modifier, b.row);
    }
  }
  return "state.?";
}

}  // namespace

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

// The selector fields a state binding's name spells (StateName): face, index, coordinate,
// matrix, modifier, row.
struct StateFields {
  bool face = false;
  bool index = false;
  bool coord = false;
  bool matrix = false;
};

StateFields StateNameFields(const Binding& b) {
  switch (b.state) {
    case StateItem::MaterialAmbient:
    case StateItem::MaterialDiffuse:
    case StateItem::MaterialSpecular:
    case StateItem::MaterialEmission:
    case StateItem::MaterialShininess:
    case StateItem::LightModelSceneColor:
      return {.face = true};
    case StateItem::LightAmbient:
    case StateItem::LightDiffuse:
    case StateItem::LightSpecular:
    case StateItem::LightPosition:
    case StateItem::LightAttenuation:
    case StateItem::LightSpotDirection:
    case StateItem::LightHalf:
    case StateItem::ClipPlane:
    case StateItem::TexEnvColor:
      return {.index = true};
    case StateItem::LightProdAmbient:
    case StateItem::LightProdDiffuse:
    case StateItem::LightProdSpecular:
      return {.face = true, .index = true};
    case StateItem::TexGenEye:
    case StateItem::TexGenObject:
      return {.index = true, .coord = true};
    case StateItem::MatrixRow: {
      bool numbered = b.matrix != MatrixName::Projection && b.matrix != MatrixName::Mvp;
      return {.index = numbered, .matrix = true};
    }
    case StateItem::LightModelAmbient:
    case StateItem::FogColor:
    case StateItem::FogParams:
    case StateItem::PointSize:
    case StateItem::PointAttenuation:
    case StateItem::DepthRange:
      return {};
  }
  return {.face = true, .index = true, .coord = true, .matrix = true};
}

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
      return b.result == ResultReg::TexCoord || (b.result == ResultReg::FragColor && b.indexed);
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

// Mirrors BindingName (and StateName): a field goes into the key only where the name spells
// it, so equal names give equal keys; and the name spells every field of the key
// distinctly, so different keys give different names. Keep the three in step
// (tests/arbvp/front_end_test.cpp checks them against each other).
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
