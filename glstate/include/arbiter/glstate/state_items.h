// The vocabulary of GL state that ARB programs bind (`state.*`): items, faces, matrices and
// their modifiers, as tables generated from state_items.def. Header-only; no dependencies.
#pragma once

#include <cstdint>
#include <string_view>

namespace arbiter::glstate {

enum class Face : uint8_t { Front, Back };
enum class MatrixModifier : uint8_t { None, Inverse, Transpose, InvTrans };

enum class StateSelector : uint8_t {
#define ARBITER_STATE_SELECTOR(Name, required, limit, noun) Name,
#include "arbiter/glstate/state_items.def"
};

enum class StateItem : uint8_t {
#define ARBITER_STATE_ITEM(Name, group, property, faced, spelling, glsl, spec) Name,
#include "arbiter/glstate/state_items.def"
};

enum class MatrixName : uint8_t {
#define ARBITER_STATE_MATRIX(Name, word, index, noun, spelling, glsl) Name,
#include "arbiter/glstate/state_items.def"
};

// The program kinds a state group exists in.
enum class StateStages : uint8_t { Vertex = 1, Fragment = 2, Both = 3 };
// Whether a matrix is numbered: "modelview" alone is modelview[0].
enum class MatrixIndex : uint8_t { No, Optional, Required };

struct StateSelectorInfo {
  StateSelector selector;
  bool required;           // the program must spell "[n]"; else n is 0
  std::string_view limit;  // the limit key n is checked against
  std::string_view noun;   // what n numbers ("light")
};

struct StateGroupInfo {
  std::string_view word;  // after "state."
  StateSelector selector;
  bool faced;  // some item of the group names a face after the selector
  bool coord;  // the property is followed by ".s" ".t" ".r" or ".q"
  StateStages stages;
  std::string_view noun;  // what the property word names
};

struct StateItemInfo {
  StateItem item;
  std::string_view group;
  std::string_view property;  // "spot.direction"; "" for the matrix rows
  bool faced;
  std::string_view spelling;  // "state.light[{i}].half"
  std::string_view glsl;      // see state_items.def
  std::string_view spec;
};

struct StateMatrixInfo {
  MatrixName matrix;
  std::string_view word;
  MatrixIndex index;
  std::string_view noun;      // what the number counts ("palette matrix")
  std::string_view spelling;  // "modelview[{i}]"
  std::string_view glsl;      // the GLSL 1.10 built-in, "" if none
};

inline constexpr StateSelectorInfo kStateSelectors[] = {
#define ARBITER_STATE_SELECTOR(Name, required, limit, noun) \
  {StateSelector::Name, required, limit, noun},
#include "arbiter/glstate/state_items.def"
};

inline constexpr StateGroupInfo kStateGroups[] = {
#define ARBITER_STATE_GROUP(word, selector, faced, coord, stages, noun) \
  {word, StateSelector::selector, faced, coord, StateStages::stages, noun},
#include "arbiter/glstate/state_items.def"
};

inline constexpr StateItemInfo kStateItems[] = {
#define ARBITER_STATE_ITEM(Name, group, property, faced, spelling, glsl, spec) \
  {StateItem::Name, group, property, faced, spelling, glsl, spec},
#include "arbiter/glstate/state_items.def"
};

inline constexpr StateMatrixInfo kStateMatrices[] = {
#define ARBITER_STATE_MATRIX(Name, word, index, noun, spelling, glsl) \
  {MatrixName::Name, word, MatrixIndex::index, noun, spelling, glsl},
#include "arbiter/glstate/state_items.def"
};

constexpr const StateItemInfo& GetStateItemInfo(StateItem item) {
  return kStateItems[static_cast<size_t>(item)];
}
constexpr const StateSelectorInfo& GetStateSelectorInfo(StateSelector selector) {
  return kStateSelectors[static_cast<size_t>(selector)];
}
constexpr const StateMatrixInfo& GetStateMatrixInfo(MatrixName matrix) {
  return kStateMatrices[static_cast<size_t>(matrix)];
}

// The group spelled `word`, or nullptr.
constexpr const StateGroupInfo* FindStateGroup(std::string_view word) {
  for (const StateGroupInfo& g : kStateGroups) {
    if (g.word == word) return &g;
  }
  return nullptr;
}

constexpr bool GroupInStage(const StateGroupInfo& group, bool vertex) {
  return (static_cast<uint8_t>(group.stages) & (vertex ? 1 : 2)) != 0;
}

// One vec4 of GL state, as an ARB binding names it: `state.light[2].half`,
// `state.matrix.modelview[0].invtrans.row[1]`.
struct StateRef {
  StateItem item = StateItem::MaterialAmbient;
  int32_t index = 0;  // light, clip plane, texture unit; the matrix number
  Face face = Face::Front;
  uint8_t coord = 0;  // texgen coordinate: 0 s, 1 t, 2 r, 3 q
  MatrixName matrix = MatrixName::Modelview;
  MatrixModifier modifier = MatrixModifier::None;
  uint8_t row = 0;
};

}  // namespace arbiter::glstate
