// The input generator's random source, GL state and textures. Every number comes from
// Rng through float arithmetic and sqrt only (IEEE correctly rounded), never sin, tan, pow
// or exp, whose last bits differ between C libraries, and one draw per statement (the order
// in which a call's arguments are evaluated differs between compilers): a seed draws the same
// state everywhere.
#include <algorithm>
#include <array>
#include <cmath>
#include <glm/mat4x4.hpp>

#include "exec/generate_internal.h"

namespace arbiter::arbvp::gen {

float Rng::Unit() { return static_cast<float>(Bits() >> 40) * 0x1p-24f; }

float Rng::Uniform(float lo, float hi) { return std::clamp(lo + (hi - lo) * Unit(), lo, hi); }

int Rng::Below(int n) { return static_cast<int>(Bits() % static_cast<uint64_t>(n)); }

namespace {

// SplitMix64's finaliser: spreads nearby seeds far apart.
uint64_t Mix(uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

Vec4 RandomVec4(Rng* rng, float lo, float hi) {
  Vec4 v{};
  for (float& c : v) c = rng->Uniform(lo, hi);
  return v;
}

// A colour with every component in [0, 1].
Vec4 RandomColor(Rng* rng) { return RandomVec4(rng, 0.0f, 1.0f); }

// A direction of length in [0.25, 1] before normalisation (rejection sampling in the unit
// ball keeps it uniform), then unit length.
glm::vec3 RandomDirection(Rng* rng) {
  for (;;) {
    glm::vec3 v;
    for (int i = 0; i < 3; ++i) v[i] = rng->Uniform(-1.0f, 1.0f);
    float len2 = v.x * v.x + v.y * v.y + v.z * v.z;
    if (len2 >= 0.0625f && len2 <= 1.0f) return v / std::sqrt(len2);
  }
}

// A uniformly random rotation (the 3x3 matrix of a unit quaternion from rejection sampling
// in the 4-ball), column-major as glm: r[column][row].
using Mat3 = std::array<std::array<float, 3>, 3>;
Mat3 RandomRotation(Rng* rng) {
  for (;;) {
    float w = rng->Uniform(-1.0f, 1.0f);
    float x = rng->Uniform(-1.0f, 1.0f);
    float y = rng->Uniform(-1.0f, 1.0f);
    float z = rng->Uniform(-1.0f, 1.0f);
    float len2 = w * w + x * x + y * y + z * z;
    if (len2 < 0.0625f || len2 > 1.0f) continue;
    float len = std::sqrt(len2);
    w /= len;
    x /= len;
    y /= len;
    z /= len;
    Mat3 r;
    r[0] = {1.0f - 2.0f * (y * y + z * z), 2.0f * (x * y + w * z), 2.0f * (x * z - w * y)};
    r[1] = {2.0f * (x * y - w * z), 1.0f - 2.0f * (x * x + z * z), 2.0f * (y * z + w * x)};
    r[2] = {2.0f * (x * z + w * y), 2.0f * (y * z - w * x), 1.0f - 2.0f * (x * x + y * y)};
    return r;
  }
}

// translation in [-2, 2]^3 x rotation x scale in [0.5, 2]^3 (condition number below ~60),
// composed by hand: column c < 3 is the rotation's column c times scale c, column 3 the
// translation.
glm::mat4 RandomAffine(Rng* rng) {
  Mat3 rotation = RandomRotation(rng);
  glm::mat4 m(1.0f);
  for (size_t c = 0; c < 3; ++c) {
    float scale = rng->Uniform(0.5f, 2.0f);
    for (size_t r = 0; r < 3; ++r) {
      m[static_cast<int>(c)][static_cast<int>(r)] = rotation[c][r] * scale;
    }
  }
  for (int r = 0; r < 3; ++r) m[3][r] = rng->Uniform(-2.0f, 2.0f);
  return m;
}

// A perspective projection as glFrustum builds it: fovy 30..90 degrees (drawn as
// tan(fovy / 2) in [tan 15, tan 45]), aspect 0.5..2, near 0.1..1, far near + 1..100. Never
// an orthographic one: Mesa 22.3 then reads a stale bottom row of the mvp inverse when a
// perspective mvp was inverted before on the same context (tests/runtime/mesa-deviations.md).
glm::mat4 RandomProjection(Rng* rng) {
  glm::mat4 m(0.0f);
  float f = 1.0f / rng->Uniform(0.26794919f, 1.0f);
  float aspect = rng->Uniform(0.5f, 2.0f);
  float z_near = rng->Uniform(0.1f, 1.0f);
  float z_far = z_near + rng->Uniform(1.0f, 100.0f);
  m[0][0] = f / aspect;
  m[1][1] = f;
  m[2][2] = (z_far + z_near) / (z_near - z_far);
  m[2][3] = -1.0f;
  m[3][2] = 2.0f * z_far * z_near / (z_near - z_far);
  return m;
}

MaterialState RandomMaterial(Rng* rng) {
  MaterialState m;
  m.ambient = RandomColor(rng);
  m.diffuse = RandomColor(rng);
  m.specular = RandomColor(rng);
  m.emission = RandomColor(rng);
  m.shininess = rng->Uniform(0.0f, 128.0f);
  return m;
}

LightState RandomLight(Rng* rng) {
  LightState l;
  l.ambient = RandomColor(rng);
  l.diffuse = RandomColor(rng);
  l.specular = RandomColor(rng);
  // A point light or a directional one, never at (or along) a near-zero vector.
  glm::vec3 p = RandomDirection(rng);
  p *= rng->Uniform(0.5f, 4.0f);
  float w = rng->Coin() ? 1.0f : 0.0f;
  l.position = {p.x, p.y, p.z, w};
  glm::vec3 d = RandomDirection(rng);
  l.spot_direction = {d.x, d.y, d.z};
  l.spot_exponent = rng->Uniform(0.0f, 128.0f);
  // Never 180: Mesa stores its cosine as 0 instead of -1 (a documented deviation).
  l.spot_cutoff = rng->Uniform(0.0f, 90.0f);
  l.constant_attenuation = rng->Uniform(0.5f, 2.0f);
  l.linear_attenuation = rng->Uniform(0.0f, 1.0f);
  l.quadratic_attenuation = rng->Uniform(0.0f, 1.0f);
  return l;
}

// 4 or 8 texels (power-of-two targets); 3..8 for rectangles.
int RandomSize(Rng* rng, TexDim dim) {
  if (dim == TexDim::Rect) return 3 + rng->Below(6);
  return rng->Coin() ? 8 : 4;
}

}  // namespace

uint64_t StreamSeed(uint64_t seed, uint64_t batch, Stream stream) {
  return Mix(Mix(Mix(seed) ^ batch) ^ static_cast<uint64_t>(stream));
}

GlState RandomState(Rng* rng) {
  GlState s;
  s.modelview = RandomAffine(rng);
  s.projection = RandomProjection(rng);
  for (glm::mat4& m : s.texture) m = RandomAffine(rng);
  // Program matrices stay the identity: the engines on Mesa do not model them.
  for (MaterialState& m : s.material) m = RandomMaterial(rng);
  for (LightState& l : s.light) l = RandomLight(rng);
  s.light_model_ambient = RandomColor(rng);
  for (TexGenState& t : s.texgen) {
    for (Vec4& plane : t.eye) plane = RandomVec4(rng, -2.0f, 2.0f);
    for (Vec4& plane : t.object) plane = RandomVec4(rng, -2.0f, 2.0f);
  }
  s.fog_color = RandomColor(rng);
  s.fog_density = rng->Uniform(0.0f, 2.0f);
  s.fog_start = rng->Uniform(-1.0f, 2.0f);
  s.fog_end = s.fog_start + rng->Uniform(0.5f, 10.0f);
  for (Vec4& plane : s.clip_plane) plane = RandomVec4(rng, -2.0f, 2.0f);
  s.point_size = rng->Uniform(1.0f, 16.0f);
  s.point_size_min = rng->Uniform(0.0f, 1.0f);
  s.point_size_max = rng->Uniform(16.0f, 64.0f);
  s.point_fade_threshold = rng->Uniform(0.5f, 4.0f);
  s.point_attenuation[0] = rng->Uniform(0.5f, 2.0f);
  s.point_attenuation[1] = rng->Uniform(0.0f, 1.0f);
  s.point_attenuation[2] = rng->Uniform(0.0f, 1.0f);
  for (Vec4& c : s.texenv_color) c = RandomColor(rng);
  s.depth_near = rng->Uniform(0.0f, 0.4f);
  s.depth_far = rng->Uniform(0.6f, 1.0f);
  return s;
}

Texture RandomTexture(TexTarget target, Rng* rng) {
  Texture t;
  t.dim = TargetDim(target);
  t.width = RandomSize(rng, t.dim);
  t.height = t.dim == TexDim::Tex1D ? 1 : t.dim == TexDim::Cube ? t.width : RandomSize(rng, t.dim);
  t.depth = t.dim == TexDim::Tex3D ? RandomSize(rng, t.dim) : t.dim == TexDim::Cube ? 6 : 1;
  t.filter = rng->Coin() ? TexFilter::Linear : TexFilter::Nearest;
  static constexpr TexWrap kWraps[] = {TexWrap::Repeat, TexWrap::ClampToEdge,
                                       TexWrap::MirroredRepeat};
  t.wrap = kWraps[rng->Below(3)];
  if (t.dim == TexDim::Rect) t.wrap = TexWrap::ClampToEdge;  // the only wrap GL allows
  size_t texels =
      static_cast<size_t>(t.width) * static_cast<size_t>(t.height) * static_cast<size_t>(t.depth);
  t.texels.resize(texels * 4);
  if (IsShadowTarget(target)) {
    t.depth_texture = true;
    t.compare = true;
    t.compare_func = static_cast<CompareFunc>(rng->Below(8));
    // Never Alpha: Mesa's ALPHA depth mode differs from the spec (a documented deviation).
    t.depth_mode = rng->Coin() ? DepthMode::Intensity : DepthMode::Luminance;
    for (size_t i = 0; i < texels; ++i) {
      t.texels[i * 4] = rng->Unit();
      t.texels[i * 4 + 3] = 1.0f;
    }
    return t;
  }
  for (float& c : t.texels) c = rng->Unit();
  return t;
}

}  // namespace arbiter::arbvp::gen
