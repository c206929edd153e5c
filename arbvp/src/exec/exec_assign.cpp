// Assignments "name=values" onto the execution model: one table of settable names
// (exec_io.h lists them).
#include <fmt/format.h>

#include <charconv>
#include <functional>
#include <utility>

#include "arbiter/arbvp/exec_io.h"
#include "exec/exec_io_internal.h"

namespace arbiter::arbvp {
namespace {

std::string_view Trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

bool ParseValues(std::string_view text, Values* out, std::string* error) {
  out->clear();
  while (true) {
    size_t comma = text.find(',');
    std::string_view item = Trim(text.substr(0, comma));
    float v = 0.0f;
    if (!ParseFloat(item, &v)) {
      *error = fmt::format("'{}' is not a number", item);
      return false;
    }
    out->push_back(v);
    if (comma == std::string_view::npos) return true;
    text.remove_prefix(comma + 1);
  }
}

// A name with its array indices taken out: "state.light[2].diffuse" -> pattern
// "state.light[].diffuse", indices {2}.
bool SplitName(std::string_view name, std::string* pattern, std::vector<int>* indices,
               std::string* error) {
  pattern->clear();
  indices->clear();
  for (size_t i = 0; i < name.size(); ++i) {
    if (name[i] != '[') {
      *pattern += name[i];
      continue;
    }
    size_t close = name.find(']', i);
    int value = 0;
    std::string_view digits =
        close == std::string_view::npos ? std::string_view() : name.substr(i + 1, close - i - 1);
    auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (digits.empty() || ec != std::errc() || end != digits.data() + digits.size()) {
      *error = fmt::format("bad index in '{}'", name);
      return false;
    }
    *pattern += "[]";
    indices->push_back(value);
    i = close;
  }
  return true;
}

// Where an assignment writes, given its indices, the inputs and the current vector.
struct Target {
  ExecInputs* inputs;
  InputVector* vector;
  const std::vector<int>& idx;
};

enum class Shape { Vec4, Vec3, Vec2, Scalar, Matrix };

// The storage of one assignment: `count` floats (Vec4, Vec3, Vec2, Scalar) or a matrix.
struct Place {
  std::array<float*, 4> f{};
  glm::mat4* m = nullptr;
};

Place Floats(float* a, float* b = nullptr, float* c = nullptr, float* d = nullptr) {
  return Place{{a, b, c, d}, nullptr};
}

Place Of(Vec4& v) { return Floats(&v[0], &v[1], &v[2], &v[3]); }

Place Of(std::array<float, 3>& v) { return Floats(&v[0], &v[1], &v[2]); }

Place Of(float& v) { return Floats(&v); }

Place Of(glm::mat4& m) { return Place{{}, &m}; }

struct Setter {
  std::string pattern;
  Shape shape;
  int index_limit;  // exclusive bound of the first index (0: none)
  std::function<Place(const Target&)> place;
};

// Both targets' env or local, or one ("vertex."/"fragment." prefix).
std::vector<Vec4*> ParamPlaces(ExecInputs* in, std::string_view which, bool local, int index) {
  std::vector<Vec4*> out;
  auto add = [&](ProgramParameters& p) { out.push_back(&(local ? p.local : p.env)[index]); };
  if (which != "fragment") add(in->vertex_params);
  if (which != "vertex") add(in->fragment_params);
  return out;
}

const std::vector<Setter>& Setters() {
  static const std::vector<Setter> table = [] {
    std::vector<Setter> t;
    auto vtx = [&t](std::string p, Vec4 VertexInput::*m) {
      t.push_back(
          {p, Shape::Vec4, 0, [m](const Target& x) -> Place { return Of(x.vector->vertex.*m); }});
    };
    vtx("vertex.position", &VertexInput::position);
    vtx("vertex.weight", &VertexInput::weight);
    vtx("vertex.normal", &VertexInput::normal);
    vtx("vertex.color", &VertexInput::color);
    vtx("vertex.color.primary", &VertexInput::color);
    vtx("vertex.color.secondary", &VertexInput::secondary_color);
    vtx("vertex.fogcoord", &VertexInput::fogcoord);
    vtx("vertex.matrixindex", &VertexInput::matrix_index);
    t.push_back({"vertex.texcoord", Shape::Vec4, 0,
                 [](const Target& x) -> Place { return Of(x.vector->vertex.texcoord[0]); }});
    t.push_back({"vertex.texcoord[]", Shape::Vec4, kMaxTextureCoords, [](const Target& x) -> Place {
                   return Of(x.vector->vertex.texcoord[static_cast<size_t>(x.idx[0])]);
                 }});
    t.push_back({"vertex.attrib[]", Shape::Vec4, kMaxGenericAttribs, [](const Target& x) -> Place {
                   // Generic attribute 0 is the vertex position (ARBvp 2.7).
                   if (x.idx[0] == 0) return Of(x.vector->vertex.position);
                   return Of(x.vector->vertex.generic[static_cast<size_t>(x.idx[0])]);
                 }});
    auto frag = [&t](std::string p, Vec4 FragmentInput::*m) {
      t.push_back(
          {p, Shape::Vec4, 0, [m](const Target& x) -> Place { return Of(x.vector->fragment.*m); }});
    };
    frag("fragment.color", &FragmentInput::color);
    frag("fragment.color.primary", &FragmentInput::color);
    frag("fragment.color.secondary", &FragmentInput::secondary_color);
    t.push_back({"fragment.texcoord", Shape::Vec4, 0,
                 [](const Target& x) -> Place { return Of(x.vector->fragment.texcoord[0]); }});
    t.push_back(
        {"fragment.texcoord[]", Shape::Vec4, kMaxTextureCoords, [](const Target& x) -> Place {
           return Of(x.vector->fragment.texcoord[static_cast<size_t>(x.idx[0])]);
         }});
    t.push_back({"fragment.fogcoord", Shape::Scalar, 0,
                 [](const Target& x) -> Place { return Of(x.vector->fragment.fogcoord); }});
    t.push_back({"fragment.depth", Shape::Scalar, 0,
                 [](const Target& x) -> Place { return Of(x.vector->fragment.depth); }});

    auto mat = [&t](std::string p, int limit, std::function<glm::mat4*(GlState&, int)> f) {
      t.push_back({p, Shape::Matrix, limit, [f](const Target& x) -> Place {
                     return Of(*f(x.inputs->state, x.idx.empty() ? 0 : x.idx[0]));
                   }});
    };
    mat("state.matrix.modelview", 0, [](GlState& s, int) { return &s.modelview; });
    mat("state.matrix.modelview[]", 1, [](GlState& s, int) { return &s.modelview; });
    mat("state.matrix.projection", 0, [](GlState& s, int) { return &s.projection; });
    mat("state.matrix.texture", 0, [](GlState& s, int) { return &s.texture[0]; });
    mat("state.matrix.texture[]", kMaxTextureCoords,
        [](GlState& s, int i) { return &s.texture[static_cast<size_t>(i)]; });
    mat("state.matrix.program[]", kMaxProgramMatrices,
        [](GlState& s, int i) { return &s.program[static_cast<size_t>(i)]; });

    // state.material[.front|.back].*
    using MatMember = Vec4 MaterialState::*;
    const std::pair<std::string_view, MatMember> mat_items[] = {
        {"ambient", &MaterialState::ambient},
        {"diffuse", &MaterialState::diffuse},
        {"specular", &MaterialState::specular},
        {"emission", &MaterialState::emission}};
    const std::pair<std::string_view, int> faces[] = {{"", 0}, {".front", 0}, {".back", 1}};
    for (const auto& [face, fi] : faces) {
      for (const auto& [item, m] : mat_items) {
        t.push_back({(fmt::format("state.material{}.{}", face, item)), Shape::Vec4, 0,
                     [fi = fi, m = m](const Target& x) -> Place {
                       return Of(x.inputs->state.material[static_cast<size_t>(fi)].*m);
                     }});
      }
      t.push_back({(fmt::format("state.material{}.shininess", face)), Shape::Scalar, 0,
                   [fi = fi](const Target& x) -> Place {
                     return Of(x.inputs->state.material[static_cast<size_t>(fi)].shininess);
                   }});
    }

    auto light = [&t](std::string p, Shape shape, std::function<Place(LightState&)> f) {
      t.push_back({p, shape, kMaxLights, [f](const Target& x) -> Place {
                     return f(x.inputs->state.light[static_cast<size_t>(x.idx[0])]);
                   }});
    };
    light("state.light[].ambient", Shape::Vec4, [](LightState& l) { return Of(l.ambient); });
    light("state.light[].diffuse", Shape::Vec4, [](LightState& l) { return Of(l.diffuse); });
    light("state.light[].specular", Shape::Vec4, [](LightState& l) { return Of(l.specular); });
    light("state.light[].position", Shape::Vec4, [](LightState& l) { return Of(l.position); });
    light("state.light[].spot.direction", Shape::Vec3,
          [](LightState& l) { return Of(l.spot_direction); });
    light("state.light[].spot.exponent", Shape::Scalar,
          [](LightState& l) { return Of(l.spot_exponent); });
    light("state.light[].spot.cutoff", Shape::Scalar,
          [](LightState& l) { return Of(l.spot_cutoff); });
    light("state.light[].attenuation", Shape::Vec3, [](LightState& l) {
      return Floats(&l.constant_attenuation, &l.linear_attenuation, &l.quadratic_attenuation);
    });
    t.push_back({"state.lightmodel.ambient", Shape::Vec4, 0,
                 [](const Target& x) -> Place { return Of(x.inputs->state.light_model_ambient); }});

    const char coords[] = {'s', 't', 'r', 'q'};
    for (size_t c = 0; c < 4; ++c) {
      t.push_back({(fmt::format("state.texgen[].eye.{}", coords[c])), Shape::Vec4,
                   kMaxTextureCoords, [c](const Target& x) -> Place {
                     return Of(x.inputs->state.texgen[static_cast<size_t>(x.idx[0])].eye[c]);
                   }});
      t.push_back({(fmt::format("state.texgen[].object.{}", coords[c])), Shape::Vec4,
                   kMaxTextureCoords, [c](const Target& x) -> Place {
                     return Of(x.inputs->state.texgen[static_cast<size_t>(x.idx[0])].object[c]);
                   }});
    }
    auto state_field = [&t](std::string p, Shape shape, std::function<Place(GlState&)> f) {
      t.push_back({p, shape, 0, [f](const Target& x) -> Place { return f(x.inputs->state); }});
    };
    state_field("state.fog.color", Shape::Vec4, [](GlState& s) { return Of(s.fog_color); });
    state_field("state.fog.density", Shape::Scalar, [](GlState& s) { return Of(s.fog_density); });
    state_field("state.fog.start", Shape::Scalar, [](GlState& s) { return Of(s.fog_start); });
    state_field("state.fog.end", Shape::Scalar, [](GlState& s) { return Of(s.fog_end); });
    t.push_back({"state.clip[].plane", Shape::Vec4, kMaxClipPlanes, [](const Target& x) -> Place {
                   return Of(x.inputs->state.clip_plane[static_cast<size_t>(x.idx[0])]);
                 }});
    state_field("state.point.size", Shape::Scalar, [](GlState& s) { return Of(s.point_size); });
    state_field("state.point.min", Shape::Scalar, [](GlState& s) { return Of(s.point_size_min); });
    state_field("state.point.max", Shape::Scalar, [](GlState& s) { return Of(s.point_size_max); });
    state_field("state.point.fade", Shape::Scalar,
                [](GlState& s) { return Of(s.point_fade_threshold); });
    state_field("state.point.attenuation", Shape::Vec3,
                [](GlState& s) { return Of(s.point_attenuation); });
    t.push_back({"state.texenv.color", Shape::Vec4, 0,
                 [](const Target& x) -> Place { return Of(x.inputs->state.texenv_color[0]); }});
    t.push_back(
        {"state.texenv[].color", Shape::Vec4, kMaxTextureCoords, [](const Target& x) -> Place {
           return Of(x.inputs->state.texenv_color[static_cast<size_t>(x.idx[0])]);
         }});
    state_field("state.depth.range", Shape::Vec2,
                [](GlState& s) { return Floats(&s.depth_near, &s.depth_far); });
    return t;
  }();
  return table;
}

bool StoreValues(Shape shape, const Place& place, const Values& v, std::string_view name,
                 std::string* error) {
  auto want = [&](size_t lo, size_t hi) {
    if (v.size() >= lo && v.size() <= hi) return true;
    *error = lo == hi ? fmt::format("'{}' takes {} numbers, not {}", name, lo, v.size())
                      : fmt::format("'{}' takes {} to {} numbers, not {}", name, lo, hi, v.size());
    return false;
  };
  switch (shape) {
    case Shape::Vec4: {
      if (!want(1, 4)) return false;
      Vec4 fill{0.0f, 0.0f, 0.0f, 1.0f};  // the (0,0,0,1) fill of missing components
      for (size_t i = 0; i < v.size(); ++i) fill[i] = v[i];
      for (size_t i = 0; i < 4; ++i) *place.f[i] = fill[i];
      return true;
    }
    case Shape::Vec3:
    case Shape::Vec2:
    case Shape::Scalar: {
      size_t n = shape == Shape::Vec3 ? 3 : shape == Shape::Vec2 ? 2 : 1;
      if (!want(n, n)) return false;
      for (size_t i = 0; i < n; ++i) *place.f[i] = v[i];
      return true;
    }
    case Shape::Matrix: {
      if (!want(16, 16)) return false;
      // Row-major text; glm (like GL) is column-major: m[column][row].
      for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) (*place.m)[c][r] = v[static_cast<size_t>(r * 4 + c)];
      }
      return true;
    }
  }
  return false;
}

}  // namespace

bool ParseFloat(std::string_view text, float* out) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty()) return false;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), *out);
  return ec == std::errc() && end == text.data() + text.size();
}

bool Assign(std::string_view name, const Values& values, ExecInputs* inputs, InputVector* vector,
            std::string* error) {
  std::string pattern;
  std::vector<int> idx;
  if (!SplitName(name, &pattern, &idx, error)) return false;

  // program.env / program.local, optionally for one target.
  for (std::string_view which : {"", "vertex.", "fragment."}) {
    for (bool local : {false, true}) {
      std::string p = fmt::format("{}program.{}[]", which, local ? "local" : "env");
      if (pattern != p) continue;
      if (idx[0] < 0 || idx[0] >= kMaxProgramParams) {
        *error = fmt::format("index {} of '{}' is out of range [0, {})", idx[0], name,
                             kMaxProgramParams);
        return false;
      }
      std::string_view target = which.empty() ? "" : which.substr(0, which.size() - 1);
      for (Vec4* place : ParamPlaces(inputs, target, local, idx[0])) {
        if (!StoreValues(Shape::Vec4, Of(*place), values, name, error)) return false;
      }
      return true;
    }
  }

  for (const Setter& s : Setters()) {
    if (s.pattern != pattern) continue;
    if (s.index_limit > 0 && (idx[0] < 0 || idx[0] >= s.index_limit)) {
      *error = fmt::format("index {} of '{}' is out of range [0, {})", idx[0], name, s.index_limit);
      return false;
    }
    return StoreValues(s.shape, s.place(Target{inputs, vector, idx}), values, name, error);
  }
  *error = fmt::format("'{}' names nothing that can be set", name);
  return false;
}

bool ApplyAssignment(std::string_view assignment, ExecInputs* inputs, InputVector* vector,
                     std::string* error) {
  size_t eq = assignment.find('=');
  if (eq == std::string_view::npos) {
    *error = fmt::format("'{}' is not NAME=VALUES", assignment);
    return false;
  }
  Values values;
  std::string_view name = Trim(assignment.substr(0, eq));
  if (!ParseValues(assignment.substr(eq + 1), &values, error)) {
    *error = fmt::format("'{}': {}", name, *error);
    return false;
  }
  return Assign(name, values, inputs, vector, error);
}

}  // namespace arbiter::arbvp
