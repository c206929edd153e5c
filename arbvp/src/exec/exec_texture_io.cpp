// Textures of the execution model: generated patterns, the --texture flag and the JSON
// texture objects.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <utility>

#include "arbiter/arbvp/exec_io.h"
#include "exec/exec_io_internal.h"

namespace arbiter::arbvp {
namespace {

// Any case: the ARB spelling (2D, CUBE, RECT) as the lower-case one.
bool ParseDim(std::string_view s, TexDim* dim) {
  for (TexDim d : {TexDim::Tex1D, TexDim::Tex2D, TexDim::Tex3D, TexDim::Cube, TexDim::Rect}) {
    std::string_view name = TexDimName(d);
    if (s.size() == name.size() && std::equal(s.begin(), s.end(), name.begin(), [](char a, char b) {
          return std::toupper(static_cast<unsigned char>(a)) == b;
        })) {
      *dim = d;
      return true;
    }
  }
  return false;
}

bool ParseFilter(std::string_view s, TexFilter* f) {
  if (s == "nearest")
    *f = TexFilter::Nearest;
  else if (s == "linear")
    *f = TexFilter::Linear;
  else
    return false;
  return true;
}

bool ParseWrap(std::string_view s, TexWrap* w) {
  if (s == "repeat")
    *w = TexWrap::Repeat;
  else if (s == "clamp")
    *w = TexWrap::ClampToEdge;
  else if (s == "mirror")
    *w = TexWrap::MirroredRepeat;
  else
    return false;
  return true;
}

bool ParseCompareFunc(std::string_view s, CompareFunc* f) {
  static const std::pair<std::string_view, CompareFunc> kFuncs[] = {
      {"never", CompareFunc::Never},     {"less", CompareFunc::Less},
      {"equal", CompareFunc::Equal},     {"lequal", CompareFunc::Lequal},
      {"greater", CompareFunc::Greater}, {"notequal", CompareFunc::Notequal},
      {"gequal", CompareFunc::Gequal},   {"always", CompareFunc::Always}};
  for (const auto& [name, v] : kFuncs) {
    if (s == name) {
      *f = v;
      return true;
    }
  }
  return false;
}

bool ParseDepthMode(std::string_view s, DepthMode* m) {
  if (s == "luminance")
    *m = DepthMode::Luminance;
  else if (s == "intensity")
    *m = DepthMode::Intensity;
  else if (s == "alpha")
    *m = DepthMode::Alpha;
  else
    return false;
  return true;
}

// "4", "4x4", "4x4x2".
bool ParseSize(std::string_view s, std::array<int, 3>* size) {
  *size = {1, 1, 1};
  for (size_t i = 0; i < 3; ++i) {
    size_t x = s.find('x');
    std::string_view part = s.substr(0, x);
    auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), (*size)[i]);
    if (part.empty() || ec != std::errc() || end != part.data() + part.size() || (*size)[i] < 1 ||
        (*size)[i] > 4096) {
      return false;
    }
    if (x == std::string_view::npos) return true;
    s.remove_prefix(x + 1);
  }
  return false;
}

// Texel count of a texture of the given dimension and size (cube maps have six faces).
bool CheckTextureShape(Texture* t, std::string* error) {
  if (t->dim == TexDim::Tex1D) t->height = 1;
  if (t->dim != TexDim::Tex3D) t->depth = 1;
  if (t->dim == TexDim::Cube) {
    if (t->width != t->height) {
      *error = "cube map faces must be square";
      return false;
    }
    t->depth = 6;
  }
  if (t->dim == TexDim::Rect && t->wrap != TexWrap::ClampToEdge) {
    // GL rejects REPEAT and MIRRORED_REPEAT for rectangle textures.
    t->wrap = TexWrap::ClampToEdge;
  }
  size_t want = static_cast<size_t>(t->width) * static_cast<size_t>(t->height) *
                static_cast<size_t>(t->depth) * 4;
  if (t->texels.size() != want) {
    *error = fmt::format("texture has {} texel values, its size needs {}", t->texels.size(), want);
    return false;
  }
  return true;
}

bool JsonString(const nlohmann::json& obj, const char* key, std::string* out) {
  auto it = obj.find(key);
  if (it == obj.end()) return true;
  if (!it->is_string()) return false;
  *out = it->get<std::string>();
  return true;
}

}  // namespace

bool ParseUnit(std::string_view s, int* unit) {
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), *unit);
  return !s.empty() && ec == std::errc() && end == s.data() + s.size() && *unit >= 0 &&
         *unit < kMaxTextureImageUnits;
}

bool ParseTextureJson(const nlohmann::json& j, Texture* t, std::string* error) {
  if (!j.is_object()) {
    *error = "a texture is an object";
    return false;
  }
  std::string target = "2d", pattern, filter = "nearest", wrap = "repeat", compare, mode;
  if (!JsonString(j, "target", &target) || !JsonString(j, "pattern", &pattern) ||
      !JsonString(j, "filter", &filter) || !JsonString(j, "wrap", &wrap) ||
      !JsonString(j, "compare", &compare) || !JsonString(j, "depth_mode", &mode)) {
    *error = "texture fields target, pattern, filter, wrap, compare, depth_mode are strings";
    return false;
  }
  TexDim dim = TexDim::Tex2D;
  if (!ParseDim(target, &dim)) {
    *error = fmt::format("unknown texture target '{}' (1d, 2d, 3d, cube, rect)", target);
    return false;
  }
  std::array<int, 3> size{1, 1, 1};
  if (auto it = j.find("size"); it != j.end()) {
    if (!it->is_array() || it->empty() || it->size() > 3) {
      *error = "texture size is a list of 1 to 3 integers";
      return false;
    }
    for (size_t i = 0; i < it->size(); ++i) {
      if (!(*it)[i].is_number_integer() || (*it)[i].get<int>() < 1 || (*it)[i].get<int>() > 4096) {
        *error = "texture size is a list of 1 to 3 integers in [1, 4096]";
        return false;
      }
      size[i] = (*it)[i].get<int>();
    }
  }
  if (!pattern.empty()) {
    if (!MakePatternTexture(pattern, dim, size[0], size[1], size[2], t)) {
      *error = fmt::format("unknown texture pattern '{}'", pattern);
      return false;
    }
  } else {
    *t = Texture{};
    t->dim = dim;
    t->width = size[0];
    t->height = size[1];
    t->depth = size[2];
    Values texels;
    auto it = j.find("texels");
    if (it == j.end()) {
      *error = "a texture needs a pattern or texels";
      return false;
    }
    if (!JsonValues(*it, &texels, "texels", error)) return false;
    t->texels = std::move(texels);
  }
  if (!ParseFilter(filter, &t->filter) || !ParseWrap(wrap, &t->wrap)) {
    *error = fmt::format("bad filter '{}' or wrap '{}'", filter, wrap);
    return false;
  }
  if (auto it = j.find("depth"); it != j.end()) {
    if (!it->is_boolean()) {
      *error = "texture field depth is true or false";
      return false;
    }
    t->depth_texture = it->get<bool>();
  }
  if (!compare.empty()) {
    t->compare = compare != "none";
    if (t->compare && !ParseCompareFunc(compare, &t->compare_func)) {
      *error = fmt::format("unknown compare function '{}'", compare);
      return false;
    }
  }
  if (!mode.empty() && !ParseDepthMode(mode, &t->depth_mode)) {
    *error = fmt::format("unknown depth mode '{}' (luminance, intensity, alpha)", mode);
    return false;
  }
  return CheckTextureShape(t, error);
}

bool MakePatternTexture(std::string_view pattern, TexDim dim, int width, int height, int depth,
                        Texture* texture) {
  Texture t;
  t.dim = dim;
  t.width = width;
  t.height = dim == TexDim::Tex1D ? 1 : height;
  t.depth = dim == TexDim::Tex3D ? depth : dim == TexDim::Cube ? 6 : 1;
  const bool checker = pattern == "checker";
  const bool gradient = pattern == "gradient";
  const bool depth_gradient = pattern == "depth-gradient" || pattern == "depth-gradient-compare";
  if (!checker && !gradient && !depth_gradient) return false;
  t.depth_texture = depth_gradient;
  t.compare = pattern == "depth-gradient-compare";
  auto centre = [](int i, int n) { return (static_cast<float>(i) + 0.5f) / static_cast<float>(n); };
  t.texels.reserve(static_cast<size_t>(t.width * t.height * t.depth) * 4);
  for (int z = 0; z < t.depth; ++z) {
    for (int y = 0; y < t.height; ++y) {
      for (int x = 0; x < t.width; ++x) {
        Vec4 c{0.0f, 0.0f, 0.0f, 1.0f};
        if (checker) {
          float on = (x + y + z) % 2 == 0 ? 1.0f : 0.0f;
          c = {on, on, on, 1.0f};
        } else if (gradient) {
          c = {centre(x, t.width), centre(y, t.height), centre(z, t.depth), 1.0f};
        } else {
          c = {centre(x, t.width), 0.0f, 0.0f, 1.0f};
        }
        t.texels.insert(t.texels.end(), c.begin(), c.end());
      }
    }
  }
  *texture = std::move(t);
  return true;
}

bool ApplyTextureFlag(std::string_view flag, ExecInputs* inputs, std::string* error) {
  size_t eq = flag.find('=');
  int unit = 0;
  if (eq == std::string_view::npos || !ParseUnit(flag.substr(0, eq), &unit)) {
    *error = fmt::format(
        "'{}' is not UNIT=TARGET:PATTERN[:SIZE][:FILTER][:WRAP] with a unit "
        "in [0, {})",
        flag, kMaxTextureImageUnits);
    return false;
  }
  std::vector<std::string_view> parts;
  std::string_view rest = flag.substr(eq + 1);
  while (true) {
    size_t colon = rest.find(':');
    parts.push_back(rest.substr(0, colon));
    if (colon == std::string_view::npos) break;
    rest.remove_prefix(colon + 1);
  }
  TexDim dim = TexDim::Tex2D;
  if (parts.size() < 2 || !ParseDim(parts[0], &dim)) {
    *error =
        fmt::format("'{}': the target (1d, 2d, 3d, cube, rect) and a pattern come first", flag);
    return false;
  }
  std::array<int, 3> size{4, 4, 4};
  TexFilter filter = TexFilter::Nearest;
  TexWrap wrap = TexWrap::Repeat;
  for (size_t i = 2; i < parts.size(); ++i) {
    std::array<int, 3> parsed{};
    if (ParseSize(parts[i], &parsed)) {
      size = parsed;
    } else if (!ParseFilter(parts[i], &filter) && !ParseWrap(parts[i], &wrap)) {
      *error = fmt::format("'{}': '{}' is no size (WxH), filter or wrap mode", flag, parts[i]);
      return false;
    }
  }
  Texture t;
  if (!MakePatternTexture(parts[1], dim, size[0], size[1], size[2], &t)) {
    *error = fmt::format(
        "'{}': unknown pattern '{}' (checker, gradient, depth-gradient, "
        "depth-gradient-compare)",
        flag, parts[1]);
    return false;
  }
  t.filter = filter;
  t.wrap = wrap;
  if (!CheckTextureShape(&t, error)) return false;
  inputs->textures[unit] = std::move(t);
  return true;
}

}  // namespace arbiter::arbvp
