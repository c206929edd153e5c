// Canonical spellings of bindings, as the specs write them.
#include <fmt/format.h>

#include "arbiter/arbvp/ir.h"

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
