// The canonical ARB spellings of state bindings, written and read back from the tables of
// state_items.def: "state.light[1].half", "state.material.back.shininess",
// "state.texgen[0].eye.s", "state.matrix.modelview[0].invtrans.row[2]", and whole matrices,
// "state.matrix.program[0].inverse". Canonical means as arbiter writes them (arbvp's
// BindingName, the binding map): the face always spelled ("front" too), numbered matrices
// always with their number ("modelview[0]"), no optional shorthands ("state.matrix.modelview",
// "state.lightmodel.scenecolor"), indices in decimal without leading zeros.
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <string>
#include <string_view>

#include "arbiter/glstate/state_items.h"

namespace arbiter::glstate {

// The suffix each MatrixModifier adds to a matrix's spelling, in enum order.
inline constexpr std::string_view kMatrixModifierSpellings[] = {"", ".inverse", ".transpose",
                                                                ".invtrans"};
static_assert(std::size(kMatrixModifierSpellings) ==
              static_cast<size_t>(MatrixModifier::InvTrans) + 1);

// A whole matrix: what a mat4 uniform holds ("state.matrix.program[0].inverse").
struct MatrixRef {
  MatrixName matrix = MatrixName::Modelview;
  int32_t index = 0;  // 0 for matrices that are not numbered
  MatrixModifier modifier = MatrixModifier::None;
};

namespace detail {

inline constexpr std::string_view kFaceSpellings[] = {"front", "back"};
inline constexpr std::string_view kCoordSpellings = "strq";

// The matrix row item's spelling split around its matrix: "state.matrix." and ".row[{r}]".
inline constexpr std::string_view kMatrixRowSpelling =
    kStateItems[static_cast<size_t>(StateItem::MatrixRow)].spelling;
inline constexpr std::string_view kMatrixPrefix =
    kMatrixRowSpelling.substr(0, kMatrixRowSpelling.find("{m}"));
inline constexpr std::string_view kMatrixSuffix =
    kMatrixRowSpelling.substr(kMatrixRowSpelling.find("{m}") + 3);

// Appends `spelling` with ref's fields in place of its {f} {i} {c} {m} {r}.
inline void Spell(std::string_view spelling, const StateRef& ref, std::string* out) {
  for (size_t brace; (brace = spelling.find('{')) != std::string_view::npos;) {
    out->append(spelling.substr(0, brace));
    const char field = spelling[brace + 1];
    spelling.remove_prefix(brace + 3);  // past "{x}"
    switch (field) {
      case 'f':
        out->append(kFaceSpellings[ref.face == Face::Back ? 1 : 0]);
        break;
      case 'i':
        out->append(std::to_string(ref.index));
        break;
      case 'c':
        out->push_back(kCoordSpellings[ref.coord & 3]);
        break;
      case 'm':
        Spell(GetStateMatrixInfo(ref.matrix).spelling, ref, out);
        out->append(kMatrixModifierSpellings[static_cast<size_t>(ref.modifier)]);
        break;
      case 'r':
        out->append(std::to_string(ref.row));
        break;
      default:
        break;
    }
  }
  out->append(spelling);
}

// A canonical decimal integer at the start of `text` (0, or no leading zero), within int32.
inline bool ReadNumber(std::string_view* text, int32_t* value) {
  size_t n = 0;
  int64_t v = 0;
  while (n < text->size() && (*text)[n] >= '0' && (*text)[n] <= '9') {
    v = v * 10 + ((*text)[n] - '0');
    if (v > std::numeric_limits<int32_t>::max()) return false;
    ++n;
  }
  if (n == 0 || (n > 1 && (*text)[0] == '0')) return false;
  text->remove_prefix(n);
  *value = static_cast<int32_t>(v);
  return true;
}

// Whether `text` is exactly the concatenation of `pieces` (spellings whose {f} {i} {c} {r}
// fields are read into `ref`; {m} is expanded by the caller).
inline bool MatchSpelling(std::initializer_list<std::string_view> pieces, std::string_view text,
                          StateRef* ref) {
  for (std::string_view piece : pieces) {
    while (!piece.empty()) {
      if (piece[0] != '{') {
        const std::string_view literal = piece.substr(0, piece.find('{'));
        if (!text.starts_with(literal)) return false;
        text.remove_prefix(literal.size());
        piece.remove_prefix(literal.size());
        continue;
      }
      const char field = piece.size() >= 3 ? piece[1] : '\0';
      piece.remove_prefix(piece.size() >= 3 ? 3 : piece.size());
      switch (field) {
        case 'f': {
          bool found = false;
          for (size_t f = 0; f < std::size(kFaceSpellings) && !found; ++f) {
            if (text.starts_with(kFaceSpellings[f])) {
              ref->face = static_cast<Face>(f);
              text.remove_prefix(kFaceSpellings[f].size());
              found = true;
            }
          }
          if (!found) return false;
          break;
        }
        case 'i':
          if (!ReadNumber(&text, &ref->index)) return false;
          break;
        case 'c': {
          const size_t c = text.empty() ? std::string_view::npos : kCoordSpellings.find(text[0]);
          if (c == std::string_view::npos) return false;
          ref->coord = static_cast<uint8_t>(c);
          text.remove_prefix(1);
          break;
        }
        case 'r': {
          int32_t row = 0;
          if (!ReadNumber(&text, &row) || row > 3) return false;
          ref->row = static_cast<uint8_t>(row);
          break;
        }
        default:
          return false;
      }
    }
  }
  return text.empty();
}

// Reads "<matrix><modifier>" + `suffix` (after the caller's prefix) into ref's matrix, index
// and modifier.
inline bool MatchMatrix(std::string_view text, std::string_view suffix, StateRef* ref) {
  for (const StateMatrixInfo& matrix : kStateMatrices) {
    for (size_t m = 0; m < std::size(kMatrixModifierSpellings); ++m) {
      StateRef candidate;
      candidate.item = ref->item;
      candidate.matrix = matrix.matrix;
      candidate.modifier = static_cast<MatrixModifier>(m);
      if (MatchSpelling({matrix.spelling, kMatrixModifierSpellings[m], suffix}, text, &candidate)) {
        *ref = candidate;
        return true;
      }
    }
  }
  return false;
}

}  // namespace detail

// The canonical spelling of a state binding. Only the fields the item's spelling shows are
// read (a material's face, a light's index, a matrix row's matrix, index, modifier and row).
inline std::string StateSpelling(const StateRef& ref) {
  std::string out;
  detail::Spell(GetStateItemInfo(ref.item).spelling, ref, &out);
  return out;
}

// The canonical spelling of a whole matrix: "state.matrix.mvp.inverse".
inline std::string MatrixSpelling(const MatrixRef& matrix) {
  StateRef ref;
  ref.item = StateItem::MatrixRow;
  ref.matrix = matrix.matrix;
  ref.index = matrix.index;
  ref.modifier = matrix.modifier;
  std::string out(detail::kMatrixPrefix);
  detail::Spell("{m}", ref, &out);
  return out;
}

// Reads a canonical state binding spelling into `ref` (every field the spelling does not
// show keeps StateRef's default). False, leaving `ref` alone, for anything else.
[[nodiscard]] inline bool ParseStateSpelling(std::string_view text, StateRef* ref) {
  for (const StateItemInfo& item : kStateItems) {
    StateRef candidate;
    candidate.item = item.item;
    if (item.item == StateItem::MatrixRow) {
      if (!text.starts_with(detail::kMatrixPrefix)) continue;
      if (!detail::MatchMatrix(text.substr(detail::kMatrixPrefix.size()), detail::kMatrixSuffix,
                               &candidate)) {
        continue;
      }
    } else if (!detail::MatchSpelling({item.spelling}, text, &candidate)) {
      continue;
    }
    *ref = candidate;
    return true;
  }
  return false;
}

// Reads a canonical whole-matrix spelling ("state.matrix.program[0].inverse"). False,
// leaving `matrix` alone, for anything else (a row of a matrix included).
[[nodiscard]] inline bool ParseMatrixSpelling(std::string_view text, MatrixRef* matrix) {
  if (!text.starts_with(detail::kMatrixPrefix)) return false;
  StateRef ref;
  ref.item = StateItem::MatrixRow;
  if (!detail::MatchMatrix(text.substr(detail::kMatrixPrefix.size()), "", &ref)) return false;
  *matrix = {ref.matrix, ref.index, ref.modifier};
  return true;
}

}  // namespace arbiter::glstate
