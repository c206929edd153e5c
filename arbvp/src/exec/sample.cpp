// Texture sampling: cube face selection (GL 2.0 table 3.20), wrap modes (3.8.7), nearest and
// linear filtering of one level (3.8.8, 3.8.9), depth textures and comparison (3.8.5, 3.8.14)
// and the consistency rules of ARB_fragment_program_shadow.
#include "exec/sample.h"

#include <algorithm>
#include <cmath>

namespace arbiter::arbvp::exec {
namespace {

bool Complete(const Texture& tex) {
  if (tex.width < 1 || tex.height < 1 || tex.depth < 1) return false;
  if (tex.dim == TexDim::Cube && (tex.depth != 6 || tex.width != tex.height)) return false;
  size_t texels = static_cast<size_t>(tex.width) * static_cast<size_t>(tex.height) *
                  static_cast<size_t>(tex.depth) * 4;
  return tex.texels.size() == texels;
}

// One axis of the lookup: the texel coordinate u (= s * size, or s for RECT) after wrapping.
struct Axis {
  int size = 1;
  TexWrap wrap = TexWrap::Repeat;
  bool rect = false;
};

// Wraps a normalised coordinate (3.8.7); RECT coordinates are unnormalised and only clamp
// to the edge ([0.5, size - 0.5], ARB_texture_rectangle).
float WrapToTexel(const Axis& axis, float s) {
  float n = static_cast<float>(axis.size);
  if (axis.rect) return std::clamp(s, 0.5f, n - 0.5f);
  float lo = 1.0f / (2.0f * n);
  float hi = 1.0f - lo;
  switch (axis.wrap) {
    case TexWrap::Repeat:
      s = s - std::floor(s);
      break;
    case TexWrap::ClampToEdge:
      s = std::clamp(s, lo, hi);
      break;
    case TexWrap::MirroredRepeat: {
      float f = std::floor(s);
      bool odd = std::fmod(f, 2.0f) != 0.0f;
      s = odd ? 1.0f - (s - f) : s - f;
      s = std::clamp(s, lo, hi);
      break;
    }
  }
  return s * n;
}

// Equations 3.23-3.25: the nearest texel (s == 1 selects the last one).
int NearestIndex(const Axis& axis, float u) {
  int i = static_cast<int>(std::floor(u));
  return std::clamp(i, 0, axis.size - 1);
}

// The two texels and weight of linear filtering along one axis (3.8.8).
struct LinearTaps {
  int i0 = 0;
  int i1 = 0;
  float alpha = 0.0f;
};
LinearTaps LinearIndices(const Axis& axis, float u) {
  float shifted = u - 0.5f;
  float f = std::floor(shifted);
  LinearTaps taps;
  taps.alpha = shifted - f;
  int i0 = static_cast<int>(f);
  if (!axis.rect && axis.wrap == TexWrap::Repeat) {
    taps.i0 = ((i0 % axis.size) + axis.size) % axis.size;
    taps.i1 = (taps.i0 + 1) % axis.size;
  } else {
    // Clamped coordinates keep i0 and i1 inside the image except where the weight of the
    // outside texel is 0 (u = size - 0.5): clamping that index changes nothing.
    taps.i0 = std::clamp(i0, 0, axis.size - 1);
    taps.i1 = std::clamp(i0 + 1, 0, axis.size - 1);
  }
  return taps;
}

// A texture image: one 2D slice of a 3D texture or one face of a cube.
struct Image {
  const Texture* tex = nullptr;
  int layer_base = 0;  // first texel of the face (cube)

  Vec4 Texel(int i, int j, int k) const {
    size_t index =
        (static_cast<size_t>(layer_base) +
         (static_cast<size_t>(k) * static_cast<size_t>(tex->height) + static_cast<size_t>(j)) *
             static_cast<size_t>(tex->width) +
         static_cast<size_t>(i)) *
        4;
    return {tex->texels[index], tex->texels[index + 1], tex->texels[index + 2],
            tex->texels[index + 3]};
  }
};

// What a texel contributes to filtering: its colour, or for a depth texture r of 3.8.14
// (the depth itself, or the comparison result) in every channel.
struct TexelReader {
  Image image;
  bool depth = false;
  bool compare = false;
  CompareFunc func = CompareFunc::Lequal;
  float ref = 0.0f;  // R clamped to [0, 1]

  Vec4 Read(int i, int j, int k) const {
    Vec4 c = image.Texel(i, j, k);
    if (!depth) return c;
    float d = std::clamp(c[0], 0.0f, 1.0f);  // "Dt, the depth texture value, in [0, 1]"
    float r = compare ? Compare(d) : d;
    return {r, r, r, r};
  }
  float Compare(float d) const {
    bool pass = false;
    switch (func) {
      case CompareFunc::Never:
        pass = false;
        break;
      case CompareFunc::Less:
        pass = ref < d;
        break;
      case CompareFunc::Equal:
        pass = ref == d;
        break;
      case CompareFunc::Lequal:
        pass = ref <= d;
        break;
      case CompareFunc::Greater:
        pass = ref > d;
        break;
      case CompareFunc::Notequal:
        pass = ref != d;
        break;
      case CompareFunc::Gequal:
        pass = ref >= d;
        break;
      case CompareFunc::Always:
        pass = true;
        break;
    }
    return pass ? 1.0f : 0.0f;
  }
};

Vec4 Mix(const Vec4& acc, const Vec4& texel, float weight) {
  return {acc[0] + weight * texel[0], acc[1] + weight * texel[1], acc[2] + weight * texel[2],
          acc[3] + weight * texel[3]};
}

// Filters at texel coordinates (u, v, w); `dims` is 1, 2 or 3.
Vec4 Filter(const TexelReader& reader, const std::array<Axis, 3>& axes, int dims, float u, float v,
            float w, TexFilter filter) {
  if (filter == TexFilter::Nearest) {
    int i = NearestIndex(axes[0], u);
    int j = dims > 1 ? NearestIndex(axes[1], v) : 0;
    int k = dims > 2 ? NearestIndex(axes[2], w) : 0;
    return reader.Read(i, j, k);
  }
  LinearTaps a = LinearIndices(axes[0], u);
  LinearTaps b = dims > 1 ? LinearIndices(axes[1], v) : LinearTaps{};
  LinearTaps c = dims > 2 ? LinearIndices(axes[2], w) : LinearTaps{};
  // Equation 3.26 and its 1D and 3D forms, term by term in the spec's order.
  Vec4 acc{0.0f, 0.0f, 0.0f, 0.0f};
  if (dims == 1) {
    acc = Mix(acc, reader.Read(a.i0, 0, 0), 1.0f - a.alpha);
    acc = Mix(acc, reader.Read(a.i1, 0, 0), a.alpha);
    return acc;
  }
  int k_count = dims > 2 ? 2 : 1;
  for (int kk = 0; kk < k_count; ++kk) {
    float gw = dims > 2 ? (kk == 0 ? 1.0f - c.alpha : c.alpha) : 1.0f;
    int k = kk == 0 ? c.i0 : c.i1;
    acc = Mix(acc, reader.Read(a.i0, b.i0, k), (1.0f - a.alpha) * (1.0f - b.alpha) * gw);
    acc = Mix(acc, reader.Read(a.i1, b.i0, k), a.alpha * (1.0f - b.alpha) * gw);
    acc = Mix(acc, reader.Read(a.i0, b.i1, k), (1.0f - a.alpha) * b.alpha * gw);
    acc = Mix(acc, reader.Read(a.i1, b.i1, k), a.alpha * b.alpha * gw);
  }
  return acc;
}

// Table 3.20: the face and its (s, t) for direction (rx, ry, rz). Returns false when the
// major axis is ambiguous (the spec lets the implementation pick) or the vector is zero.
bool SelectCubeFace(float rx, float ry, float rz, int* face, float* s, float* t) {
  float ax = std::fabs(rx);
  float ay = std::fabs(ry);
  float az = std::fabs(rz);
  float sc = 0.0f;
  float tc = 0.0f;
  float ma = 0.0f;
  if (ax > ay && ax > az) {
    *face = rx >= 0.0f ? 0 : 1;
    sc = rx >= 0.0f ? -rz : rz;
    tc = -ry;
    ma = rx;
  } else if (ay > ax && ay > az) {
    *face = ry >= 0.0f ? 2 : 3;
    sc = rx;
    tc = ry >= 0.0f ? rz : -rz;
    ma = ry;
  } else if (az > ax && az > ay) {
    *face = rz >= 0.0f ? 4 : 5;
    sc = rz >= 0.0f ? rx : -rx;
    tc = -ry;
    ma = rz;
  } else {
    return false;
  }
  *s = 0.5f * (sc / std::fabs(ma) + 1.0f);
  *t = 0.5f * (tc / std::fabs(ma) + 1.0f);
  return true;
}

Vec4 DepthToRgba(float r, DepthMode mode) {
  switch (mode) {
    case DepthMode::Luminance:
      return {r, r, r, 1.0f};
    case DepthMode::Intensity:
      return {r, r, r, r};
    case DepthMode::Alpha:
      return {0.0f, 0.0f, 0.0f, r};
  }
  return {r, r, r, 1.0f};
}

}  // namespace

}  // namespace arbiter::arbvp::exec

namespace arbiter::arbvp {

std::string_view TexDimName(TexDim dim) {
  switch (dim) {
    case TexDim::Tex1D:
      return "1D";
    case TexDim::Tex2D:
      return "2D";
    case TexDim::Tex3D:
      return "3D";
    case TexDim::Cube:
      return "CUBE";
    case TexDim::Rect:
      return "RECT";
  }
  return "?";
}

namespace {
// What the interpreter needs of a target (texture_targets.def).
struct TargetRow {
  TexDim dim;
  bool depth;
};
constexpr TargetRow kTargets[] = {
#define ARBVP_TEX_TARGET(name, spelling, coords, shadow, dim, grad, mipmaps, depth, ...) \
  {TexDim::dim, depth},
#include "arbiter/arbvp/texture_targets.def"
#undef ARBVP_TEX_TARGET
};
const TargetRow& Row(TexTarget target) { return kTargets[static_cast<size_t>(target)]; }
// A non-shadow target that may sample a depth texture (1D, 2D, RECT).
bool IsDepthCapableNonShadow(TexTarget target) {
  return !TexTargetIsShadow(target) && Row(target).depth;
}
}  // namespace

TexDim TargetDim(TexTarget target) { return Row(target).dim; }

bool IsShadowTarget(TexTarget target) { return TexTargetIsShadow(target); }

}  // namespace arbiter::arbvp

namespace arbiter::arbvp::exec {

Sample SampleTexture(const std::map<int, Texture>& textures, int unit, TexTarget target, float s,
                     float t, float r, bool shadow_option) {
  Sample out;
  auto it = textures.find(unit);
  if (it == textures.end()) return out;
  const Texture& tex = it->second;
  if (tex.dim != TargetDim(target) || !Complete(tex)) return out;

  bool shadow = IsShadowTarget(target);
  // ARB_fragment_program_shadow: without the option a 1D/2D/RECT sample behaves as if the
  // compare mode were NONE; with it, a target inconsistent with the texture is undefined.
  bool compare = shadow;
  if (shadow && !(tex.depth_texture && tex.compare)) {
    out.undefined = tex.depth_texture
                        ? "a SHADOW target samples a depth texture whose compare mode is NONE"
                        : "a SHADOW target samples a texture that is not a depth texture";
  }
  if (shadow_option && tex.depth_texture && tex.compare && IsDepthCapableNonShadow(target)) {
    out.undefined = "a non-SHADOW target samples a depth texture with depth comparison enabled";
  }

  int dims = 2;
  Image image{&tex, 0};
  float cs = s;
  float ct = t;
  float cr = r;
  switch (tex.dim) {
    case TexDim::Tex1D:
      dims = 1;
      break;
    case TexDim::Tex2D:
    case TexDim::Rect:
      dims = 2;
      break;
    case TexDim::Tex3D:
      dims = 3;
      break;
    case TexDim::Cube: {
      int face = 0;
      if (!std::isfinite(s) || !std::isfinite(t) || !std::isfinite(r) ||
          !SelectCubeFace(s, t, r, &face, &cs, &ct)) {
        if (out.undefined.empty()) {
          out.undefined = "a cube map direction without a unique major axis";
        }
        face = 0;
        cs = 0.5f;
        ct = 0.5f;
      }
      image.layer_base = face * tex.width * tex.height;
      dims = 2;
      if (tex.filter == TexFilter::Linear) {
        float u = cs * static_cast<float>(tex.width);
        float v = ct * static_cast<float>(tex.height);
        out.cube_edge = !(u >= 0.5f && u <= static_cast<float>(tex.width) - 0.5f && v >= 0.5f &&
                          v <= static_cast<float>(tex.height) - 0.5f);
      }
      break;
    }
  }
  bool finite =
      std::isfinite(cs) && (dims < 2 || std::isfinite(ct)) && (dims < 3 || std::isfinite(cr));
  if (!finite) {
    if (out.undefined.empty()) out.undefined = "a texture coordinate that is infinite or NaN";
    cs = std::isfinite(cs) ? cs : 0.0f;
    ct = std::isfinite(ct) ? ct : 0.0f;
    cr = std::isfinite(cr) ? cr : 0.0f;
  }

  bool rect = tex.dim == TexDim::Rect;
  std::array<Axis, 3> axes{Axis{tex.width, tex.wrap, rect},
                           Axis{tex.dim == TexDim::Tex1D ? 1 : tex.height, tex.wrap, rect},
                           Axis{tex.dim == TexDim::Tex3D ? tex.depth : 1, tex.wrap, rect}};
  float u = WrapToTexel(axes[0], cs);
  float v = dims > 1 ? WrapToTexel(axes[1], ct) : 0.0f;
  float w = dims > 2 ? WrapToTexel(axes[2], cr) : 0.0f;
  if (tex.filter == TexFilter::Linear && tex.wrap == TexWrap::MirroredRepeat && !rect) {
    const std::array<float, 3> coords{cs, ct, cr};
    const std::array<float, 3> texels{u, v, w};
    for (int i = 0; i < dims; ++i) {
      bool mirrored = std::fmod(std::floor(coords[static_cast<size_t>(i)]), 2.0f) != 0.0f;
      float shifted = texels[static_cast<size_t>(i)] - 0.5f;
      float alpha = shifted - std::floor(shifted);
      out.mirror_centre =
          out.mirror_centre || (mirrored && (alpha < 0x1p-8f || alpha > 1.0f - 0x1p-8f));
    }
  }

  TexelReader reader;
  reader.image = image;
  reader.depth = tex.depth_texture;
  reader.compare = compare && tex.depth_texture;
  reader.func = tex.compare_func;
  // R: the r coordinate clamped to [0, 1] (SHADOW1D uses s and r, the others s, t, r).
  reader.ref = std::isfinite(r) ? std::clamp(r, 0.0f, 1.0f) : (r > 0.0f ? 1.0f : 0.0f);
  if (std::isnan(r) && reader.compare && out.undefined.empty()) {
    out.undefined = "a depth comparison with a NaN r coordinate";
  }
  if (reader.compare && tex.filter == TexFilter::Linear && out.undefined.empty()) {
    // 3.8.14: with a LINEAR filter "r may be computed by comparing more than one depth
    // texture value ... The details of this are implementation-dependent".
    out.undefined = "linear filtering of a depth comparison (implementation-dependent)";
  }
  Vec4 value = Filter(reader, axes, dims, u, v, w, tex.filter);
  out.value = tex.depth_texture ? DepthToRgba(value[0], tex.depth_mode) : value;
  return out;
}

}  // namespace arbiter::arbvp::exec
