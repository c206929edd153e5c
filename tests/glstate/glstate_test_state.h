// Shared by the glstate tests: GL state whose derived values differ from every input, and
// every state binding the tables spell.
#pragma once

#include <array>
#include <glm/mat4x4.hpp>
#include <string_view>
#include <vector>

#include "arbiter/arbvp/ir.h"
#include "arbiter/glstate/gl_state.h"
#include "arbiter/glstate/state_items.h"

namespace arbiter::glstate::test {

// Matrices by rows, as ARB reads them. modelview: scale (2, 4, 8), then translate (1, 2, 3).
inline constexpr std::array<Vec4, 4> kModelviewRows = {Vec4{2, 0, 0, 1}, Vec4{0, 4, 0, 2},
                                                       Vec4{0, 0, 8, 3}, Vec4{0, 0, 0, 1}};
inline constexpr std::array<Vec4, 4> kProjectionRows = {Vec4{1, 0, 0, 0}, Vec4{0, 1, 0, 0},
                                                        Vec4{0, 0, -1, -2}, Vec4{0, 0, -1, 0}};
inline constexpr std::array<Vec4, 4> kTextureRows = {Vec4{0, 1, 0, 0.5f}, Vec4{-1, 0, 0, 0.25f},
                                                     Vec4{0, 0, 1, 0}, Vec4{0, 0, 0, 1}};
inline constexpr std::array<Vec4, 4> kProgramRows = {Vec4{1, 2, 3, 4}, Vec4{0, 1, 5, 6},
                                                     Vec4{0, 0, 1, 7}, Vec4{0, 0, 0, 2}};

// GL (and GLM) hold matrices by columns: m[c][r] is row r of column c.
inline glm::mat4 FromRows(const std::array<Vec4, 4>& rows) {
  glm::mat4 m(1.0f);
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      m[c][r] = rows[static_cast<size_t>(r)][static_cast<size_t>(c)];
    }
  }
  return m;
}

// Values chosen so that the products and sums of the derivations are exact in binary.
inline GlState RichState() {
  GlState s;
  s.modelview = FromRows(kModelviewRows);
  s.projection = FromRows(kProjectionRows);
  s.texture[3] = FromRows(kTextureRows);
  s.program[5] = FromRows(kProgramRows);
  MaterialState& front = s.material[0];
  front.ambient = {0.5f, 0.5f, 0.25f, 0.125f};
  front.diffuse = {0.5f, 0.25f, 0.125f, 0.75f};
  front.specular = {1, 1, 1, 0.5f};
  front.emission = {0.25f, 0.125f, 0.5f, 0.0625f};
  front.shininess = 12;
  MaterialState& back = s.material[1];
  back.ambient = {1, 0.5f, 0.5f, 0.5f};
  back.diffuse = {0.25f, 0.5f, 1, 0.5f};
  back.specular = {0.5f, 0.5f, 0.5f, 0.25f};
  back.emission = {0.5f, 0.5f, 0.5f, 1};
  back.shininess = 64;
  s.light_model_ambient = {0.5f, 0.25f, 2, 1};
  LightState& l1 = s.light[1];
  l1.ambient = {0.5f, 0.25f, 0.5f, 2};
  l1.diffuse = {0.5f, 2, 4, 0.25f};
  l1.specular = {1, 0.5f, 0.25f, 4};
  l1.position = {0, 6, 0, -2};
  l1.spot_direction = {0, -1, 0};
  l1.spot_exponent = 16;
  l1.spot_cutoff = 45;
  l1.constant_attenuation = 0.5f;
  l1.linear_attenuation = 0.25f;
  l1.quadratic_attenuation = 0.125f;
  s.light[2].position = {3, 0, 4, 0};
  s.light[2].spot_cutoff = 90;
  s.light[3].position = {2, 0, 0, 1};
  s.fog_color = {0.25f, 0.5f, 0.75f, 1};
  s.fog_density = 0.5f;
  s.fog_start = 2;
  s.fog_end = 6;
  s.point_size = 4;
  s.point_size_min = 1;
  s.point_size_max = 16;
  s.point_fade_threshold = 2;
  s.point_attenuation = {1, 0.5f, 0.25f};
  s.texenv_color[3] = {0.125f, 0.25f, 0.375f, 0.5f};
  s.clip_plane[4] = {1, -1, 0.5f, 3};
  for (size_t c = 0; c < 4; ++c) {
    const float base = static_cast<float>(4 * c);
    s.texgen[2].eye[c] = {base + 1, base + 2, base + 3, base + 4};
    s.texgen[2].object[c] = {-(base + 1), -(base + 2), -(base + 3), -(base + 4)};
  }
  s.depth_near = 0.25f;
  s.depth_far = 0.75f;
  return s;
}

inline bool Shows(std::string_view spelling, std::string_view field) {
  return spelling.find(field) != std::string_view::npos;
}

// Every state binding the tables spell: each item with each face, coordinate, matrix,
// modifier and row its spelling shows, at indices inside and just past the model.
inline std::vector<StateRef> AllRefs() {
  const std::vector<int32_t> indices = {0, 1, 2, 3, 5, 7, 8, 12};
  std::vector<StateRef> refs;
  for (const StateItemInfo& item : kStateItems) {
    const bool matrix = Shows(item.spelling, "{m}");
    const size_t matrices = matrix ? std::size(kStateMatrices) : 1;
    for (size_t m = 0; m < matrices; ++m) {
      const std::string_view matrix_spelling = matrix ? kStateMatrices[m].spelling : "";
      const bool indexed = Shows(item.spelling, "{i}") || Shows(matrix_spelling, "{i}");
      for (const int32_t index : indexed ? indices : std::vector<int32_t>{0}) {
        for (int face = 0; face < (Shows(item.spelling, "{f}") ? 2 : 1); ++face) {
          for (int coord = 0; coord < (Shows(item.spelling, "{c}") ? 4 : 1); ++coord) {
            for (int modifier = 0; modifier < (matrix ? 4 : 1); ++modifier) {
              for (int row = 0; row < (Shows(item.spelling, "{r}") ? 4 : 1); ++row) {
                StateRef ref;
                ref.item = item.item;
                ref.index = index;
                ref.face = static_cast<Face>(face);
                ref.coord = static_cast<uint8_t>(coord);
                ref.matrix = matrix ? kStateMatrices[m].matrix : MatrixName::Modelview;
                ref.modifier = static_cast<MatrixModifier>(modifier);
                ref.row = static_cast<uint8_t>(row);
                refs.push_back(ref);
              }
            }
          }
        }
      }
    }
  }
  return refs;
}

// The interpreter's binding for `ref`.
inline arbvp::Binding BindingOf(const StateRef& ref) {
  arbvp::Binding b;
  b.kind = arbvp::BindingKind::State;
  b.state = ref.item;
  b.index = ref.index;
  b.face = ref.face;
  b.coord = ref.coord;
  b.matrix = ref.matrix;
  b.modifier = ref.modifier;
  b.row = ref.row;
  return b;
}

}  // namespace arbiter::glstate::test
