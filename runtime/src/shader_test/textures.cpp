// piglit's generated textures (`texture ...`) and `texparameter`. The patterns are piglit's
// (piglit-util-gl.c), checked against its shader_runner: rgbw quadrants red, green, blue,
// white from the bottom-left; a depth ramp i / (w - 1) along s for the shadow textures; a
// checkerboard of half-size squares; an 8x8 mipmap of solid red, green, blue, white levels.
// Every texture filters NEAREST and clamps to the edge unless texparameter says otherwise.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>

#include "shader_test/gl_names.h"
#include "shader_test/session.h"
#include "shader_test/words.h"

namespace arbiter::runtime::shader_test {
namespace {

using Rgba = std::array<float, 4>;

constexpr Rgba kRed{1, 0, 0, 1};
constexpr Rgba kGreen{0, 1, 0, 1};
constexpr Rgba kBlue{0, 0, 1, 1};
constexpr Rgba kWhite{1, 1, 1, 1};

// The quadrant pattern of an rgbw texture at texel (x, y) of a w x h image.
Rgba Quadrant(int x, int y, int w, int h, const Rgba& ll, const Rgba& lr, const Rgba& ul,
              const Rgba& ur) {
  const bool right = x >= w / 2;
  const bool top = y >= h / 2;
  return top ? (right ? ur : ul) : (right ? lr : ll);
}

void Put(std::vector<float>* image, const Rgba& c) {
  image->insert(image->end(), c.begin(), c.end());
}

}  // namespace

void Session::Texture(const std::vector<std::string>& a) {
  if (a.empty()) Error("expected 'texture KIND ...'");
  const std::string& kind = a[0];
  // The unit follows the kind, or the kind's target word (rgbw 1D, rgbw 3D).
  const bool targeted = kind == "rgbw" && a.size() > 1 && (a[1] == "1D" || a[1] == "3D");
  const size_t unit_at = targeted ? 2 : 1;
  const int unit = Int(a, unit_at);
  if (unit < 0 || unit >= 16) Error(fmt::format("texture unit {} out of range", unit));
  auto expect = [&](size_t count, const char* usage) {
    if (a.size() != count) Error(fmt::format("expected 'texture {}'", usage));
  };
  auto size = [&](size_t i) {
    const int v = Int(a, i);
    if (v < 1 || v > 4096) Error(fmt::format("texture size {} out of range", v));
    return v;
  };

  GLenum target = GL_TEXTURE_2D;
  std::vector<float> image;
  int w = 1, h = 1, d = 1;
  GLenum format = GL_RGBA;
  GLenum internal = GL_RGBA8;
  int level = 0;
  std::vector<std::vector<float>> levels;  // miptree: every level
  std::array<Rgba, 6> faces{};             // cubefaces
  if (kind == "rgbw" && targeted && a[1] == "1D") {
    expect(3, "rgbw 1D unit");
    target = GL_TEXTURE_1D;
    w = 4;
    for (const Rgba& c : {kRed, kGreen, kBlue, kWhite}) Put(&image, c);
  } else if (kind == "rgbw" && targeted) {
    expect(3, "rgbw 3D unit");
    target = GL_TEXTURE_3D;
    w = h = d = 2;
    const Rgba yellow{1, 1, 0, 1}, magenta{1, 0, 1, 1}, cyan{0, 1, 1, 1}, black{0, 0, 0, 1};
    for (int z = 0; z < d; ++z) {
      for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
          Put(&image, z == 0 ? Quadrant(x, y, w, h, kRed, kGreen, kBlue, kWhite)
                             : Quadrant(x, y, w, h, yellow, magenta, cyan, black));
        }
      }
    }
  } else if (kind == "rgbw") {
    if (a.size() != 4 && a.size() != 5) expect(4, "rgbw unit (w, h)");
    w = size(2);
    h = size(3);
    if (a.size() == 5) internal = Enum(a[4]);
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) Put(&image, Quadrant(x, y, w, h, kRed, kGreen, kBlue, kWhite));
    }
  } else if (kind == "checkerboard") {
    expect(13, "checkerboard unit level (w, h) (r, g, b, a) (r, g, b, a)");
    level = Int(a, 2);
    w = size(3);
    h = size(4);
    const Rgba c1{Float(a, 5), Float(a, 6), Float(a, 7), Float(a, 8)};
    const Rgba c2{Float(a, 9), Float(a, 10), Float(a, 11), Float(a, 12)};
    const int sw = std::max(w / 2, 1), sh = std::max(h / 2, 1);
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) Put(&image, ((x / sw) + (y / sh)) % 2 != 0 ? c2 : c1);
    }
  } else if (kind == "quads") {
    // texture quads unit level (w, h) (qw, qh) (c1) (c2) (c3) (c4): qw x qh blocks whose
    // colour follows the parity of their column and row: c1 (even, even), c2 (odd, even),
    // c3 (even, odd), c4 (odd, odd), from the bottom-left (as piglit's shader_runner draws it).
    expect(23, "quads unit level (w, h) (qw, qh) (c1) (c2) (c3) (c4)");
    level = Int(a, 2);
    w = size(3);
    h = size(4);
    const int qw = std::max(Int(a, 5), 1), qh = std::max(Int(a, 6), 1);
    std::array<Rgba, 4> c{};
    for (size_t q = 0; q < 4; ++q) {
      for (size_t k = 0; k < 4; ++k) c[q][k] = Float(a, 7 + q * 4 + k);
    }
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        Put(&image, c[static_cast<size_t>((x / qw) % 2 + 2 * ((y / qh) % 2))]);
      }
    }
  } else if (kind == "miptree") {
    expect(2, "miptree unit");
    w = h = 8;
    const std::array<Rgba, 4> colors{kRed, kGreen, kBlue, kWhite};
    for (int l = 0, s = 8; s >= 1; ++l, s /= 2) {
      std::vector<float> pixels;
      for (int i = 0; i < s * s; ++i) Put(&pixels, colors[static_cast<size_t>(l)]);
      levels.push_back(std::move(pixels));
    }
  } else if (kind == "shadow2D" || kind == "shadowRect" || kind == "shadow1D") {
    const bool one = kind == "shadow1D";
    expect(one ? 3 : 4, one ? "shadow1D unit (w)" : "shadow2D unit (w, h)");
    target = one ? GL_TEXTURE_1D : kind == "shadowRect" ? GL_TEXTURE_RECTANGLE_ARB : GL_TEXTURE_2D;
    w = size(2);
    h = one ? 1 : size(3);
    format = GL_DEPTH_COMPONENT;
    internal = GL_DEPTH_COMPONENT24;
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        image.push_back(w > 1 ? static_cast<float>(x) / static_cast<float>(w - 1) : 0.0f);
      }
    }
  } else if (kind == "cubefaces") {
    expect(3, "cubefaces unit (size)");
    target = GL_TEXTURE_CUBE_MAP;
    w = h = size(2);
    faces = {Rgba{1, 0, 0, 1}, Rgba{0, 1, 1, 1}, Rgba{0, 1, 0, 1},
             Rgba{1, 0, 1, 1}, Rgba{0, 0, 1, 1}, Rgba{1, 1, 0, 1}};
  } else {
    Error(fmt::format("unknown texture kind '{}'", kind));
  }

  target = TranslatedTexTarget(target, unit);
  GLuint id = 0;
  gl_.ActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
  // A new texture has GL's initial GL_DEPTH_TEXTURE_MODE (--translate's state).
  state_.depth_texture_mode[static_cast<size_t>(unit)] = glstate::kDepthModeLuminance;
  gl_.GenTextures(1, &id);
  textures_.push_back(id);
  gl_.BindTexture(target, id);
  const GLenum type = GL_FLOAT;
  if (!levels.empty()) {
    for (size_t l = 0, s = 8; l < levels.size(); ++l, s /= 2) {
      gl_.TexImage2D(target, static_cast<GLint>(l), static_cast<GLint>(internal),
                     static_cast<GLsizei>(s), static_cast<GLsizei>(s), 0, format, type,
                     levels[l].data());
    }
  } else if (target == GL_TEXTURE_CUBE_MAP) {
    for (size_t f = 0; f < 6; ++f) {
      std::vector<float> pixels;
      for (int i = 0; i < w * h; ++i) Put(&pixels, faces[f]);
      gl_.TexImage2D(static_cast<GLenum>(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f), 0,
                     static_cast<GLint>(internal), w, h, 0, format, type, pixels.data());
    }
  } else if (target == GL_TEXTURE_1D) {
    gl_.TexImage1D(target, level, static_cast<GLint>(internal), w, 0, format, type, image.data());
  } else if (target == GL_TEXTURE_3D) {
    gl_.TexImage3D(target, level, static_cast<GLint>(internal), w, h, d, 0, format, type,
                   image.data());
  } else {
    gl_.TexImage2D(target, level, static_cast<GLint>(internal), w, h, 0, format, type,
                   image.data());
  }
  gl_.TexParameteri(target, GL_TEXTURE_MIN_FILTER,
                    levels.empty() ? GL_NEAREST : GL_NEAREST_MIPMAP_NEAREST);
  gl_.TexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  if (levels.empty() && level == 0) gl_.TexParameteri(target, GL_TEXTURE_MAX_LEVEL, 0);
  for (GLenum wrap :
       {GLenum{GL_TEXTURE_WRAP_S}, GLenum{GL_TEXTURE_WRAP_T}, GLenum{GL_TEXTURE_WRAP_R}}) {
    gl_.TexParameteri(target, wrap, GL_CLAMP_TO_EDGE);
  }
  if (format == GL_DEPTH_COMPONENT) {
    // piglit's shadow textures compare with GREATER from the start.
    gl_.TexParameteri(target, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    gl_.TexParameteri(target, GL_TEXTURE_COMPARE_FUNC, GL_GREATER);
  }
  gl_.Enable(target);  // for the fixed-function fragment stage, as piglit does
}

GLenum Session::TranslatedTexTarget(GLenum target, int unit) const {
  if (!StateUniforms() || (target != GL_TEXTURE_1D && target != GL_TEXTURE_RECTANGLE_ARB)) {
    return target;
  }
  for (const arbvp::SamplerBinding& s : bindings_.samplers) {
    if (s.unit == unit && arbvp::UploadsAs2D(s)) return GL_TEXTURE_2D;
  }
  return target;
}

void Session::TexParameter(const std::vector<std::string>& a) {
  if (a.size() < 3) Error("expected 'texparameter TARGET PARAMETER VALUE'");
  static constexpr std::array<std::pair<std::string_view, GLenum>, 6> kTargets{{
      {"1D", GL_TEXTURE_1D},
      {"2D", GL_TEXTURE_2D},
      {"3D", GL_TEXTURE_3D},
      {"Rect", GL_TEXTURE_RECTANGLE_ARB},
      {"Cube", GL_TEXTURE_CUBE_MAP},
      {"2DArray", GL_TEXTURE_2D_ARRAY},
  }};
  static constexpr std::array<std::pair<std::string_view, GLenum>, 11> kParameters{{
      {"compare_func", GL_TEXTURE_COMPARE_FUNC},
      {"compare_mode", GL_TEXTURE_COMPARE_MODE},
      {"depth_mode", GL_DEPTH_TEXTURE_MODE},
      {"min", GL_TEXTURE_MIN_FILTER},
      {"mag", GL_TEXTURE_MAG_FILTER},
      {"wrap_s", GL_TEXTURE_WRAP_S},
      {"wrap_t", GL_TEXTURE_WRAP_T},
      {"wrap_r", GL_TEXTURE_WRAP_R},
      {"lod_bias", GL_TEXTURE_LOD_BIAS},
      {"max_level", GL_TEXTURE_MAX_LEVEL},
      {"base_level", GL_TEXTURE_BASE_LEVEL},
  }};
  GLenum target = 0;
  for (const auto& [name, value] : kTargets) {
    if (name == a[0]) target = value;
  }
  if (target == 0) Error(fmt::format("unknown texture target '{}'", a[0]));
  GLint active = GL_TEXTURE0;
  gl_.GetIntegerv(GL_ACTIVE_TEXTURE, &active);
  target = TranslatedTexTarget(target, active - GL_TEXTURE0);
  if (a[1] == "border_color") {
    if (a.size() != 6) Error("expected 'texparameter TARGET border_color (r, g, b, a)'");
    const float color[4] = {Float(a, 2), Float(a, 3), Float(a, 4), Float(a, 5)};
    gl_.TexParameterfv(target, GL_TEXTURE_BORDER_COLOR, color);
    return;
  }
  GLenum parameter = 0;
  for (const auto& [name, value] : kParameters) {
    if (name == a[1]) parameter = value;
  }
  if (parameter == 0) Error(fmt::format("unknown texture parameter '{}'", a[1]));
  if (a.size() != 3) Error(fmt::format("texparameter {} takes one value", a[1]));
  if (parameter == GL_TEXTURE_LOD_BIAS) {
    gl_.TexParameterf(target, parameter, Float(a, 2));
  } else if (parameter == GL_TEXTURE_MAX_LEVEL || parameter == GL_TEXTURE_BASE_LEVEL) {
    gl_.TexParameteri(target, parameter, Int(a, 2));
  } else {
    // Values are GL enum names in lower case without the prefix ("greater", "clamp_to_edge",
    // "compare_r_to_texture").
    std::string name = "GL_" + a[2];
    std::transform(name.begin(), name.end(), name.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    const GLenum value = Enum(name);
    gl_.TexParameteri(target, parameter, static_cast<GLint>(value));
    if (parameter == GL_DEPTH_TEXTURE_MODE) {  // for --translate's state as uniforms
      const int unit = active - GL_TEXTURE0;
      if (unit >= 0 && unit < glstate::kMaxTextureImageUnits) {
        state_.depth_texture_mode[static_cast<size_t>(unit)] = value;
      }
    }
  }
}

}  // namespace arbiter::runtime::shader_test
